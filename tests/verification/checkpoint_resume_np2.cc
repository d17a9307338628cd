// checkpoint_resume.cc on two ranks: the checkpoint holds each rank's part,
// and a resume on one rank must be refused.
#include "checkpoint_resume.cc"
