#!/usr/bin/env bash
# Bad scenes that cannot be single files in tests/bad_input/: include
# cycles (the files must name each other), 1 MB expressions, a scene too
# large for a memory limit (ulimit -v), and profile times beyond the end.
#   scene_checks.sh LIFTOFF
# Every refusal must be short: a non-zero exit code, the named message, at
# most two lines on stderr and 1000 bytes, no stack trace, no output folder.
set -u
liftoff=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
tests=$(cd "$(dirname "$0")" && pwd)
source "$tests/../common/output_checks.sh"
enter_work_directory

# refused NAME REGEX SCENE [LIMIT_KB]: run SCENE (under ulimit -v LIMIT_KB
# if given) and check the refusal.
refused() {
  local name=$1 expect=$2 scene=$3 limit=${4:-unlimited}
  (ulimit -v "$limit"; "$liftoff" "$scene" >stdout.txt 2>stderr.txt)
  local status=$?
  head -c 600 stderr.txt; echo
  [ "$status" -ne 0 ]; check $? "$name: exit code is non-zero ($status)"
  grep -Eq -- "$expect" stderr.txt; check $? "$name: message matches /$expect/"
  local lines bytes
  lines=$(grep -c . stderr.txt)
  bytes=$(wc -c < stderr.txt)
  [ "$lines" -le 2 ] && [ "$bytes" -le 1000 ]
  check $? "$name: at most 2 lines and 1000 bytes on stderr ($lines, $bytes)"
  ! grep -Eq 'Stacktrace|std::bad_alloc|INFOG' stderr.txt
  check $? "$name: no stack trace, bad_alloc or solver dump"
  [ ! -e out ]; check $? "$name: no output folder"
  rm -rf out
}

loaded='subsection Loads
  subsection Point load 1
    set Magnitude = 1
  end
end
subsection Output
  set Directory = out
end'

# Include cycles: two files naming each other, and a file in a subfolder
# naming itself (include paths are relative to the folder of the file that
# holds the include line). A diamond (two includes of one file) is no cycle
# and must run.
printf 'include b.prm\n%s\n' "$loaded" > a.prm
printf '# the other half of the cycle\n  include   a.prm   # comment\n' > b.prm
refused "a.prm -> b.prm -> a.prm" 'include lines form a cycle: a\.prm -> b\.prm -> a\.prm' a.prm
mkdir -p sub
printf 'INCLUDE self.prm\n' > sub/self.prm
refused "self include" 'include lines form a cycle: sub/self\.prm -> sub/self\.prm' sub/self.prm
printf 'subsection Time integration\n  set End time = 0.001\nend\n' > leaf.prm
printf 'include leaf.prm\n' > left.prm
printf 'include leaf.prm\n' > right.prm
printf 'include left.prm\ninclude right.prm\n%s\n' "$loaded" > diamond.prm
"$liftoff" diamond.prm >/dev/null 2>stderr.txt
check $? "a diamond of includes runs: $(head -c 200 stderr.txt)"
rm -rf out

# Includes beside the scene, run from another folder: found relative to the
# including file (deal.II alone looks them up from the working directory),
# through two levels; a scene with a UTF-8 byte order mark runs; a bad line
# in an included file is named by that file and its own line number; a
# missing include names the file looked for and the line naming it; a
# folder given as a scene is named as such.
mkdir -p studies/common elsewhere
printf 'subsection Time integration\n  set End time = 0.001\nend\n' > studies/common/time.prm
printf '\xEF\xBB\xBF# shared settings\ninclude time.prm\n' > studies/common/all.prm
printf '\xEF\xBB\xBFinclude common/all.prm\n%s\n' "$loaded" > studies/a.prm
(cd elsewhere && "$liftoff" ../studies/a.prm >/dev/null 2>../stderr.txt)
check $? "includes beside the scene, run from elsewhere: $(head -c 300 stderr.txt)"
grep -q '^0.001,' elsewhere/out/history.csv
check $? "the included End time = 0.001 was read"
rm -rf elsewhere/out
printf 'subsection Plate\n\n  set Thicknes = 0.1\nend\n' > studies/common/typo.prm
printf '%s\n\n\ninclude common/typo.prm\n' "$loaded" > studies/b.prm
refused "misspelt entry in an include" \
  'Line <3> of file <studies/common/typo\.prm>: No entry with name <Thicknes>' studies/b.prm
printf '%s\n\ninclude nowhere.prm\n' "$loaded" > studies/c.prm
refused "missing include" 'Cannot read the scene file studies/nowhere\.prm \(named by the include line 10 of studies/c\.prm\)' studies/c.prm
refused "a folder as the scene" 'studies is a directory, not a scene file' studies

# 1 MB expressions: the message shows the parameter and the start of the
# text, not the whole text (nor deal.II's echo of it and its stack trace).
long=$(head -c 1000000 /dev/zero | tr '\0' '+')
printf '%s\nsubsection Loads\n  subsection Pressure 1\n    set Magnitude = 1\n    set Intensity = 1%s\n  end\nend\n' \
  "$loaded" "$long" > long_intensity.prm
refused "1 MB intensity" 'Loads/Pressure 1/Intensity = <1\+\+\+.*\.\.\. \(1000001 characters\)> must be a muParser expression' long_intensity.prm
printf '%s\nsubsection Initial conditions\n  set Displacement = 0; 0; x%s\nend\n' \
  "$loaded" "$long" > long_initial.prm
refused "1 MB initial displacement" 'Initial conditions/Displacement = <0; 0; x\+\+.*characters\)> must be 3 muParser expressions' long_initial.prm
ones=$(head -c 1000000 /dev/zero | tr '\0' '1')
printf 'subsection Loads\n  subsection Point load 1\n    set Magnitude = %sx\n  end\nend\n' \
  "$ones" > long_number.prm
refused "1 MB number" 'The entry value 1111.*characters left out.*for the entry named Magnitude does not match the given pattern' long_number.prm
printf '%s\nsubsection Loads\n  subsection Pressure 1\n    set Magnitude = 1\n    set Region = 0%s\n  end\nend\n' \
  "$loaded" "$long" > long_region.prm
refused "1 MB region" 'Loads/Pressure 1/Region = <0\+\+\+.*\(1000001 characters\)> must be' long_region.prm
printf '%s\nsubsection Loads\n  subsection Point load 1\n    set Time history = sin(tau\n  end\nend\n' \
  "$loaded" > short_history.prm
refused "unbalanced time history" 'Loads/Point load 1/Time history = <sin\(tau> must be a muParser expression in \(tau\): .*Missing parenthesis' short_history.prm

# A scene that needs some 20 GB (2.6e7 cells) under a 3 GB address-space
# limit: refused from the estimate, before the mesh is built. Before, the
# only message was std::bad_alloc (or the machine started swapping).
printf '%s\nsubsection Discretization\n  set Global refinements = 9\nend\n' "$loaded" > refined.prm
refused "Global refinements = 9 under ulimit -v 3 GB" \
  'Global refinements = 9, Polynomial degree = 1 make 2\.6[0-9]*e\+07 cells.*GB per rank.*only [0-9.]+ GB per rank are available' \
  refined.prm 3000000

# The same refusals on two ranks: every rank stops (no hang), rank 0 says why.
for scene in a.prm "$tests/mesh_too_large.prm" long_intensity.prm; do
  timeout 120 mpirun --allow-run-as-root --oversubscribe -np 2 "$liftoff" "$scene" >stdout.txt 2>stderr.txt
  status=$?
  [ "$status" -ne 0 ] && [ "$status" -ne 124 ]
  check $? "2 ranks, $(basename "$scene"): stops with a non-zero exit code, no hang ($status)"
  [ "$(grep -c 'liftoff: error in' stderr.txt)" -eq 1 ] &&
    grep -Eq 'form a cycle|GB per rank are available|must be a muParser' stderr.txt
  check $? "2 ranks, $(basename "$scene"): one message, from rank 0"
done

# Points on the edges of a plate wider than long (y in [-1, 1]) are on
# the plate: the check runs with the real aspect ratio, not the default
# square's. On a plate narrower than long the message names its bounds.
printf '%s\nsubsection Plate\n  set Aspect ratio = 2\nend\nsubsection Time integration\n  set End time = 0.002\nend\nsubsection Output\n  set Probe points = 0, 0.7; 0, -1; 0.5, 1\n  set Profile start = 0, -1\n  set Profile end = 0, 1\n  set Profile points = 5\nend\n' \
  "$loaded" > wide.prm
"$liftoff" wide.prm >stdout.txt 2>stderr.txt
check $? "probes and a profile to the edges of a plate of Aspect ratio = 2 run: $(head -c 300 stderr.txt)"
rm -rf out
printf '%s\nsubsection Plate\n  set Aspect ratio = 0.5\nend\nsubsection Output\n  set Probe points = 0, 0.3\nend\n' \
  "$loaded" > narrow.prm
refused "probe off a narrow plate" 'Output/Probe points: the point 0, 0\.3 lies outside the plate \[-0\.5, 0\.5\] x \[-0\.25, 0\.25\]' narrow.prm

# Probes that six digits do not tell apart get columns of their own names.
printf '%s\nsubsection Time integration\n  set End time = 0.002\nend\nsubsection Output\n  set Probe points = 0.333333, 0; 0.3333334, 0; 0.25, 0\nend\n' \
  "$loaded" > close_probes.prm
"$liftoff" close_probes.prm >stdout.txt 2>stderr.txt
check $? "probes at 0.333333 and 0.3333334 run"
header=$(head -1 out/history.csv)
echo "$header" | grep -q ',w(0.333333;0),w(0.3333334;0),w(0.25;0),'
check $? "probes at 0.333333 and 0.3333334: distinct column names ($header)"
rm -rf out

# Profile times beyond the end: the run completes, writes the profiles it
# reaches and warns about the others by name.
printf '%s\nsubsection Time integration\n  set Time step = 0.01\n  set End time = 0.05\nend\nsubsection Output\n  set Profile points = 3\n  set Profile times = 0.02, 0.3, 7\nend\n' \
  "$loaded" > late_profiles.prm
"$liftoff" late_profiles.prm >stdout.txt 2>stderr.txt
check $? "late profile times: the run completes"
cat stderr.txt
grep -q 'warning: Output/Profile times 0.3 7 lie beyond Time integration/End time = 0.05' stderr.txt
check $? "late profile times: the warning names 0.3 and 7"
taus=$(awk -F, 'NR > 1 {print $1}' out/profiles.csv | sort -u | tr '\n' ' ')
[ "$taus" = "0.02 " ]; check $? "late profile times: profiles.csv holds tau = 0.02 only ($taus)"
finish
