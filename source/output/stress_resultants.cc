#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <liftoff/fem/discretization.h>
#include <liftoff/fem/plate_fields.h>
#include <liftoff/output/stress_resultants.h>

#include <algorithm>
#include <cmath>

namespace liftoff
{
  namespace
  {
    // The order of the fields in evaluate_vector_field()'s output.
    const std::vector<std::string> names = {"M_xx",
                                            "M_yy",
                                            "M_xy",
                                            "Q_x",
                                            "Q_y",
                                            "M_1",
                                            "M_2",
                                            "M_1_angle",
                                            "sigma_xx",
                                            "sigma_yy",
                                            "sigma_xy",
                                            "sigma_max",
                                            "sigma_1_top",
                                            "sigma_1_bottom",
                                            "sigma_1_base_top",
                                            "sigma_1_base_bottom"};
    // The faces' own are in the field files on request only (Output/Face
    // stress fields); the base's where there is one.
    constexpr unsigned int n_fields_by_default = 12;
    constexpr unsigned int n_fields_of_slab    = 14;

    /// The free moments of a section, in units of D: the slab's D_s (1 +
    /// nu) kappa_T and the base's D_b (1 + nu_b) kappa_Tb, measured as the
    /// moments the section carries.
    struct FreeMoments
    {
      double slab = 0, base = 0;

      /// What M_xx, M_yy and the principal moments gain. (A base without a
      /// temperature adds nothing: + 0 would turn a -0 into 0 in the
      /// files.)
      double
      total() const
      {
        return base == 0 ? slab : slab + base;
      }
    };


    /// The free bending of the plate's section (FreeBendingField) in a
    /// section: each layer's curvature as the curvature whose moment at
    /// the plate's D is the same, the slab's stresses of E_s (the base's
    /// are of its own modulus already).
    FreeBending
    in_section(const FreeBending &thermal, const SectionCoefficients &section)
    {
      FreeBending in = thermal;
      in.curvature   = thermal.curvature * section.thermal_moment;
      in.bottom_stress *= section.modulus;
      in.top_stress *= section.modulus;
      in.base_curvature = thermal.base_curvature * section.base_thermal_moment;
      return in;
    }


    /// The free moments of `thermal` in its section (in_section()).
    FreeMoments
    free_moments(const FreeBending &thermal, const double nu)
    {
      return {(1 + nu) * thermal.curvature, (1 + nu) * thermal.base_curvature};
    }


    /// The largest principal stress at a face by its law, from the
    /// principal moments M_1 >= M_2 and the free moments of the layers'
    /// temperatures (all measured from the free curvature).
    double
    at_face(const FaceStressLaw &law,
            const double         m_1,
            const double         m_2,
            const FreeMoments   &free)
    {
      double s = std::max(law.per_moment * m_1, law.per_moment * m_2);
      // Only a base changes it (a slab alone: + 0 would turn -0 into 0).
      if (law.per_free_moment != 0)
        s += law.per_free_moment * free.slab;
      if (free.base != 0)
        s += law.per_base_free_moment * free.base;
      return s;
    }


    /// Adds `stress` to `face` where it is not 0 (+ 0 would turn a -0 into
    /// 0 in the files).
    void
    add_stress(const double stress, double &face)
    {
      if (stress != 0)
        face += stress;
    }


    /// The largest principal stress at each face of the section: at the
    /// top face (z = -H/2) and the bed-side face (z = +H/2) of a slab alone
    /// -6 M_2 / H^2 and 6 M_1 / H^2, plus a nonlinear profile's
    /// self-equilibrating stress of each face (`thermal`, in the section,
    /// with its free moments `free`; none: nullptr).
    FaceStresses
    face_stresses(const double               m_1,
                  const double               m_2,
                  const SectionCoefficients &section,
                  const FreeBending         *thermal,
                  const FreeMoments         &free)
    {
      FaceStresses s{at_face(section.top, m_1, m_2, free),
                     at_face(section.bottom, m_1, m_2, free)};
      if (section.has_base)
        {
          s.base_top    = at_face(section.base_top, m_1, m_2, free);
          s.base_bottom = at_face(section.base_bottom, m_1, m_2, free);
        }
      // Added only with a temperature: + 0 would turn a -0 into 0.
      if (thermal != nullptr)
        {
          s.top += thermal->top_stress;
          s.bottom += thermal->bottom_stress;
          add_stress(thermal->base_top_stress, s.base_top);
          add_stress(thermal->base_bottom_stress, s.base_bottom);
        }
      return s;
    }


    /// out[11..15]: sigma_max, sigma_1_top, sigma_1_bottom and the base's
    /// from M_1 and M_2 (out[5], out[6]).
    void
    set_face_stresses(const SectionCoefficients &section,
                      const FreeBending         *thermal,
                      const FreeMoments         &free,
                      Vector<double>            &out)
    {
      const FaceStresses s =
        face_stresses(out[5], out[6], section, thermal, free);
      out[11] = std::max(s.bottom, s.top);
      if (section.has_base)
        out[11] = std::max({out[11], s.base_top, s.base_bottom});
      if (out.size() > n_fields_by_default)
        {
          out[12] = s.top;
          out[13] = s.bottom;
        }
      if (out.size() > n_fields_of_slab)
        {
          out[14] = s.base_top;
          out[15] = s.base_bottom;
        }
    }


    /// The moments shifted by the free moments, the stresses at the
    /// bed-side face (sigma_xx, sigma_yy) by its law.
    void
    add_free_bending(const FreeBending         &thermal,
                     const double               nu,
                     const SectionCoefficients &section,
                     Vector<double>            &out)
    {
      const FreeMoments free = free_moments(thermal, nu);
      const double      m    = free.total();
      for (const unsigned int k : {0, 1, 5, 6})
        out[k] += m;
      double shift = section.bottom.per_moment * m;
      if (section.bottom.per_free_moment != 0)
        shift += section.bottom.per_free_moment * free.slab;
      if (free.base != 0)
        shift += section.bottom.per_base_free_moment * free.base;
      out[8] += shift + thermal.bottom_stress;
      out[9] += shift + thermal.bottom_stress;
      set_face_stresses(section, &thermal, free, out);
    }


    /// M_xx, M_yy, M_xy and the principal moments from the gradients of
    /// psi_x and psi_y; `bending`: -D_s / D (z along w).
    struct PlaneMoments
    {
      double xx, yy, xy, first, second;

      PlaneMoments(const double        bending,
                   const double        nu,
                   const Tensor<1, 2> &grad_psi_x,
                   const Tensor<1, 2> &grad_psi_y)
          : xx(bending * (grad_psi_x[0] + nu * grad_psi_y[1]))
          , yy(bending * (grad_psi_y[1] + nu * grad_psi_x[0]))
          , xy(bending * 0.5 * (1 - nu) * (grad_psi_x[1] + grad_psi_y[0]))
      {
        const double centre = 0.5 * (xx + yy);
        const double radius = std::hypot(0.5 * (xx - yy), xy);
        first               = centre + radius;
        second              = centre - radius;
      }
    };
  } // namespace


  const std::string StressResultants::sign_convention =
    "M = int sigma z dz with z along w (into the bed): a positive moment "
    "puts the bed-side face (z = +H/2) in tension; sigma_xx, sigma_yy and "
    "sigma_xy are the stresses at that face, the other face has their "
    "negatives; sigma_1_top and sigma_1_bottom are the largest principal "
    "stresses at the face away from the bed and at the bed-side face";


  StressResultants::StressResultants(
    const MindlinPlate                    &plate,
    const Mapping<2>                      &mapping,
    const TransverseShearStrain::Treatment treatment,
    const LA::MPI::Vector                 &solution,
    const FreeBendingField                &free_bending,
    const bool                             face_fields)
      : plate(plate)
      , mapping(mapping)
      , treatment(treatment)
      , solution(solution)
      , free_bending(free_bending)
      , face_fields(face_fields)
  {}


  const std::map<std::string, PhysicalUnits::Quantity> &
  StressResultants::quantities()
  {
    using Quantity = PhysicalUnits::Quantity;
    static const std::map<std::string, Quantity> table = {
      {"M_xx", Quantity::moment},
      {"M_yy", Quantity::moment},
      {"M_xy", Quantity::moment},
      {"Q_x", Quantity::force_per_length},
      {"Q_y", Quantity::force_per_length},
      {"M_1", Quantity::moment},
      {"M_2", Quantity::moment},
      {"M_1_angle", Quantity::angle_degrees},
      {"sigma_xx", Quantity::pressure},
      {"sigma_yy", Quantity::pressure},
      {"sigma_xy", Quantity::pressure},
      {"sigma_max", Quantity::pressure},
      {"sigma_1_top", Quantity::pressure},
      {"sigma_1_bottom", Quantity::pressure},
      {"sigma_1_base_top", Quantity::pressure},
      {"sigma_1_base_bottom", Quantity::pressure}};
    return table;
  }


  const std::vector<std::string> &
  StressResultants::field_names()
  {
    return names;
  }


  std::vector<std::string>
  StressResultants::get_names() const
  {
    return {names.begin(), names.begin() + n_fields(face_fields)};
  }


  unsigned int
  StressResultants::n_fields(const bool with_faces) const
  {
    if (!with_faces)
      return n_fields_by_default;
    return plate.base.present() ? names.size() : n_fields_of_slab;
  }


  UpdateFlags
  StressResultants::get_needed_update_flags() const
  {
    return update_values | update_gradients | update_quadrature_points;
  }


  void
  StressResultants::shear_strains(const DoFHandler<2>::cell_iterator &cell,
                                  const std::vector<Point<2>>   &unit_points,
                                  const ArrayView<const double> &dof_values,
                                  std::vector<Tensor<1, 2>>     &gamma) const
  {
    StrainsAtPoints &cached = strains_at_points.get();
    const auto       same   = [](const Point<2> &a, const Point<2> &b) {
      return a.distance(b) < 1e-12;
    };
    if (!cached.strains || cached.unit_points.size() != unit_points.size()
        || !std::equal(unit_points.begin(),
                       unit_points.end(),
                       cached.unit_points.begin(),
                       same))
      {
        cached.unit_points = unit_points;
        cached.strains     = std::make_unique<TransverseShearStrain>(
          mapping, cell->get_fe(), treatment, Quadrature<2>(unit_points));
      }
    TransverseShearStrain &strains = *cached.strains;
    strains.reinit(cell);

    gamma.assign(unit_points.size(), Tensor<1, 2>());
    for (unsigned int q = 0; q < unit_points.size(); ++q)
      for (unsigned int i = 0; i < dof_values.size(); ++i)
        gamma[q] += dof_values[i] * strains.strain(i, q);
  }


  void
  StressResultants::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<2> &inputs,
    std::vector<Vector<double>>              &computed) const
  {
    // DataOut gives the points in real coordinates only.
    const auto            cell   = inputs.template get_cell<2>();
    const auto           &points = inputs.evaluation_points;
    std::vector<Point<2>> unit_points(points.size());
    for (unsigned int q = 0; q < points.size(); ++q)
      unit_points[q] = GeometryInfo<2>::project_to_unit_cell(
        mapping.transform_real_to_unit_cell(cell, points[q]));
    compute(cell,
            unit_points,
            points,
            inputs.solution_values,
            inputs.solution_gradients,
            computed);
  }


  void
  StressResultants::compute(
    const DoFHandler<2>::cell_iterator           &cell,
    const std::vector<Point<2>>                  &unit_points,
    const std::vector<Point<2>>                  &points,
    const std::vector<Vector<double>>            &value,
    const std::vector<std::vector<Tensor<1, 2>>> &gradient,
    std::vector<Vector<double>>                  &computed) const
  {
    // Only the assumed strain needs the element's tying points.
    std::vector<Tensor<1, 2>> gamma(unit_points.size());
    if (treatment == TransverseShearStrain::Treatment::mitc)
      {
        Vector<double> dof_values(cell->get_fe().n_dofs_per_cell());
        cell->get_dof_values(solution, dof_values);
        shear_strains(cell,
                      unit_points,
                      ArrayView<const double>(dof_values.begin(),
                                              dof_values.size()),
                      gamma);
      }
    else
      for (unsigned int q = 0; q < unit_points.size(); ++q)
        for (unsigned int d = 0; d < 2; ++d)
          gamma[q][d] =
            gradient[q][PlateFields::w][d] - value[q][PlateFields::rotation(d)];
    const double              nu        = plate.poisson_ratio;
    const SectionCoefficients section   = plate.section(cell->material_id());
    const double              to_stress = section.bottom.per_moment;
    const double              shear     = section.shear;
    const double              bending = -section.bending; // D_s / D, z along w
    // The temperature at each point, evaluated once for both layers.
    std::vector<FreeBending> thermal(free_bending ? unit_points.size() : 0);
    for (unsigned int q = 0; q < unit_points.size(); ++q)
      {
        const PlaneMoments m(bending,
                             nu,
                             gradient[q][PlateFields::psi_x],
                             gradient[q][PlateFields::psi_y]);
        Vector<double>    &out = computed[q];
        out[0]                 = m.xx;
        out[1]                 = m.yy;
        out[2]                 = m.xy;
        out[3]                 = shear * gamma[q][0];
        out[4]                 = shear * gamma[q][1];
        out[5]                 = m.first;
        out[6]                 = m.second;
        out[7]  = 0.5 * std::atan2(2 * m.xy, m.xx - m.yy) * 180.0 / M_PI;
        out[8]  = to_stress * m.xx;
        out[9]  = to_stress * m.yy;
        out[10] = to_stress * m.xy;
        if (free_bending)
          {
            thermal[q] = free_bending(points[q]);
            add_free_bending(in_section(thermal[q], section), nu, section, out);
          }
        else
          set_face_stresses(section, nullptr, FreeMoments(), out);
      }
    add_own_base_faces(thermal, gradient, computed);
  }


  void
  StressResultants::add_own_base_faces(
    const std::vector<FreeBending>               &thermal,
    const std::vector<std::vector<Tensor<1, 2>>> &gradient,
    std::vector<Vector<double>>                  &computed) const
  {
    if (plate.base.n_layers() == 1)
      return;
    // A base of its own bends about its own mid-plane by its own psi.
    const SectionCoefficients base = plate.base_section();
    for (unsigned int q = 0; q < computed.size(); ++q)
      {
        FaceStresses faces;
        own_base_faces(base,
                       gradient[q][PlateFields::rotation(0, 1)],
                       gradient[q][PlateFields::rotation(1, 1)],
                       thermal.empty() ? nullptr : &thermal[q],
                       faces);
        Vector<double> &out = computed[q];
        out[11] = std::max({out[11], faces.base_top, faces.base_bottom});
        if (out.size() > n_fields_of_slab)
          {
            out[14] = faces.base_top;
            out[15] = faces.base_bottom;
          }
      }
  }


  void
  StressResultants::add_own_base_faces(const PlateFieldAtPoints       &fields,
                                       const std::vector<FreeBending> &thermal,
                                       PrincipalValues &out) const
  {
    // A base of its own: its faces by its own moments.
    if (!out.with_faces || fields.grad_psi_base.empty())
      return;
    const SectionCoefficients base = plate.base_section();
    for (unsigned int q = 0; q < fields.n_points(); ++q)
      own_base_faces(base,
                     fields.grad_psi_base[q][0],
                     fields.grad_psi_base[q][1],
                     thermal.empty() ? nullptr : &thermal[q],
                     out.faces[q]);
  }


  void
  StressResultants::own_base_faces(const SectionCoefficients &base,
                                   const Tensor<1, 2>        &grad_psi_x,
                                   const Tensor<1, 2>        &grad_psi_y,
                                   const FreeBending         *temperature,
                                   FaceStresses              &faces) const
  {
    PlaneMoments m(-base.bending,
                   plate.base.poisson_ratio,
                   grad_psi_x,
                   grad_psi_y);
    // Its own moments measured from its own free curvature, which stresses
    // it as a section alone: its faces by those moments.
    FreeBending thermal;
    if (temperature != nullptr)
      {
        thermal           = in_section(*temperature, base);
        const double free = free_moments(thermal, plate.poisson_ratio).total();
        m.first += free;
        m.second += free;
      }
    faces.base_top    = at_face(base.top, m.first, m.second, FreeMoments());
    faces.base_bottom = at_face(base.bottom, m.first, m.second, FreeMoments());
    add_stress(thermal.base_top_stress, faces.base_top);
    add_stress(thermal.base_bottom_stress, faces.base_bottom);
  }


  void
  StressResultants::principal(const DoFHandler<2>::active_cell_iterator &cell,
                              const PlateFieldAtPoints                  &fields,
                              const ArrayView<const double> &dof_values,
                              PrincipalValues               &out) const
  {
    const unsigned int n = fields.n_points();
    out.m_1.resize(n);
    out.m_2.resize(n);
    if (treatment == TransverseShearStrain::Treatment::mitc)
      shear_strains(cell, fields.unit_points(), dof_values, out.q);
    else
      {
        out.q.resize(n);
        for (unsigned int q = 0; q < n; ++q)
          for (unsigned int d = 0; d < 2; ++d)
            out.q[q][d] = fields.grad_w[q][d] - fields.psi[q][d];
      }
    out.faces.resize(out.with_faces ? n : 0);
    const double              nu      = plate.poisson_ratio;
    const SectionCoefficients section = plate.section(cell->material_id());
    const double              bending = -section.bending;
    // The temperature at each point, evaluated once for both layers (kept
    // for a base of its own only).
    const bool own_base = free_bending && plate.base.n_layers() == 2;
    std::vector<FreeBending> temperature(own_base ? n : 0);
    for (unsigned int q = 0; q < n; ++q)
      {
        const PlaneMoments m(bending,
                             nu,
                             fields.grad_psi[q][0],
                             fields.grad_psi[q][1]);
        out.m_1[q] = m.first;
        out.m_2[q] = m.second;
        for (unsigned int d = 0; d < 2; ++d)
          out.q[q][d] = section.shear * out.q[q][d];
        // The thermal stress of a face is wanted with the faces only; its
        // curvature always.
        FreeBending thermal;
        FreeMoments free;
        if (free_bending)
          {
            const FreeBending here = free_bending(fields.points()[q]);
            if (own_base)
              temperature[q] = here;
            thermal = in_section(here, section);
            free    = free_moments(thermal, nu);
            out.m_1[q] += free.total();
            out.m_2[q] += free.total();
          }
        if (out.with_faces)
          out.faces[q] = face_stresses(out.m_1[q],
                                       out.m_2[q],
                                       section,
                                       free_bending ? &thermal : nullptr,
                                       free);
      }
    add_own_base_faces(fields, temperature, out);
  }


  unsigned int
  StressResultants::field_index(const std::string &name)
  {
    const auto at = std::find(names.begin(), names.end(), name);
    Assert(at != names.end(), ExcInternalError());
    return at - names.begin();
  }


  void
  StressResultants::evaluate(const DoFHandler<2>::cell_iterator &cell,
                             const FEValues<2>                  &values,
                             std::vector<Vector<double>>        &computed) const
  {
    const unsigned int          n            = values.n_quadrature_points;
    const unsigned int          n_components = cell->get_fe().n_components();
    std::vector<Vector<double>> point_values(n, Vector<double>(n_components));
    std::vector<std::vector<Tensor<1, 2>>> gradients(
      n, std::vector<Tensor<1, 2>>(n_components));
    values.get_function_values(solution, point_values);
    values.get_function_gradients(solution, gradients);
    computed.resize(n, Vector<double>(names.size()));
    compute(cell,
            values.get_quadrature().get_points(),
            values.get_quadrature_points(),
            point_values,
            gradients,
            computed);
  }


  std::map<std::string, double>
  StressResultants::at_point(const Discretization &discretization,
                             const Point<2>       &p) const
  {
    const auto [cell, unit] =
      GridTools::find_active_cell_around_point(mapping,
                                               discretization.dof_handler,
                                               p);
    if (!cell->is_locally_owned())
      return {};
    const Quadrature<2> point(GeometryInfo<2>::project_to_unit_cell(unit));
    FEValues<2>         values(mapping,
                       cell->get_fe(),
                       point,
                       update_values | update_gradients
                         | update_quadrature_points);
    values.reinit(cell);
    std::vector<Vector<double>> computed;
    evaluate(cell, values, computed);

    std::map<std::string, double> fields;
    for (unsigned int k = 0; k < n_fields(true); ++k)
      fields[names[k]] = computed[0][k];
    return fields;
  }
} // namespace liftoff
