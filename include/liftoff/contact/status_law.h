#pragma once

namespace liftoff
{
  /**
   * The rule by which a point spring with a status switches: the bed's
   * contact (in contact where w - e > 0), a dowel's play (engaged where
   * |[w]| > g). A StatusTerm asks it, point by point, for the status that
   * follows from the value its points measure (w - e, [w]) and for the
   * offset of the spring's force in a status; everything else (the status
   * kept per point, the matrix brought up to date, the products with its
   * change, the checkpoint) is the term's and is written once.
   *
   * A status is a small number: 0 slack, anything else engaged, possibly
   * in a direction (a dowel pressed one way or the other).
   */
  class StatusLaw
  {
  public:
    virtual ~StatusLaw() = default;

    /// Whether a status ever changes (false: a bilateral bed, dowels
    /// without play): then the statuses stay as set up and nothing is
    /// measured.
    virtual bool
    switches() const = 0;

    /// The half-width of the round-off band, given the largest |value| of
    /// the whole plate: inside it a point may keep either status.
    virtual double
    band(const double largest) const = 0;

    /// The status of a point with `status` whose value is `value`.
    virtual unsigned char
    next_status(const unsigned char status,
                const double        value,
                const double        band) const = 0;

    /// Whether a point whose status left `earlier` may take it back at
    /// `value`: the value lies in the band, where either fits.
    virtual bool
    may_keep(const unsigned char earlier,
             const double        value,
             const double        band) const = 0;

    /// Whether the spring acts in `status`.
    static bool
    engaged(const unsigned char status)
    {
      return status != 0;
    }

    /// The status that holds both: what the iteration solves with when the
    /// statuses go round a cycle.
    virtual unsigned char
    unite(const unsigned char a, const unsigned char b) const
    {
      return a | b;
    }

    /// The springs' stiffness in a system matrix whose unknown's velocity
    /// is kappa w + ... (`velocity_factor`; 0 at a given state).
    virtual double
    stiffness(const double velocity_factor) const = 0;

    /// Whether some engaged point's force has a part that does not depend
    /// on u, k * offset: then it joins the right-hand side of every solve.
    virtual bool
    has_offset() const = 0;

    /// The force of engaged point i is k (value - offset(i, status)), k
    /// this stiffness.
    virtual double
    offset_stiffness() const = 0;

    virtual double
    offset(const unsigned int i, const unsigned char status) const = 0;
  };
} // namespace liftoff
