#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <qsmpm/base/parsed_region.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/materials/smeared_cracks.h>
#include <sstream>

namespace qsmpm
{
  namespace
  {
    /// The largest local system: dim jumps of dim cracks.
    constexpr unsigned int max_unknowns = 9;

    /// Solve A x = b (n x n, row-major in @p A) in place by Gaussian
    /// elimination with partial pivoting; false if A is singular.
    bool
    solve_dense(std::array<double, max_unknowns * max_unknowns> &A,
                std::array<double, max_unknowns>                &b,
                const unsigned int                               n)
    {
      for (unsigned int c = 0; c < n; ++c)
        {
          unsigned int pivot = c;
          for (unsigned int r = c + 1; r < n; ++r)
            if (std::abs(A[r * n + c]) > std::abs(A[pivot * n + c]))
              pivot = r;
          if (!(std::abs(A[pivot * n + c]) > 0.))
            return false;
          if (pivot != c)
            {
              for (unsigned int k = 0; k < n; ++k)
                std::swap(A[c * n + k], A[pivot * n + k]);
              std::swap(b[c], b[pivot]);
            }
          for (unsigned int r = c + 1; r < n; ++r)
            {
              const double f = A[r * n + c] / A[c * n + c];
              for (unsigned int k = c; k < n; ++k)
                A[r * n + k] -= f * A[c * n + k];
              b[r] -= f * b[c];
            }
        }
      for (int r = n - 1; r >= 0; --r)
        {
          double sum = b[r];
          for (unsigned int k = r + 1; k < n; ++k)
            sum -= A[r * n + k] * b[k];
          b[r] = sum / A[r * n + r];
        }
      return true;
    }

    /// G_ab = C_acbd n_c m_d: the traction on the plane n of the stress
    /// C : (e_b (x) m).
    template <int dim>
    Tensor<2, dim>
    coupling(const SymmetricTensor<4, dim> &C,
             const Tensor<1, dim>          &n,
             const Tensor<1, dim>          &m)
    {
      Tensor<2, dim> G;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int d = 0; d < dim; ++d)
              G[a][b] += C[a][c][b][d] * n[c] * m[d];
      return G;
    }
  } // namespace



  template <int dim>
  SmearedCracks<dim>::SmearedCracks(const Parameters &parameters)
    : C(LinearElastic<dim>::isotropic_stiffness(
        parameters.elastic.elasticity.young_modulus,
        parameters.elastic.elasticity.poisson_ratio,
        parameters.elastic.plane_stress))
    , tau_nf(parameters.tensile_strength)
    , G_f(parameters.fracture_energy)
    , delta_0((parameters.softening == Softening::bilinear ? 3.6 : 2.) *
              parameters.fracture_energy / parameters.tensile_strength)
    , band_width(parameters.crack_band_width)
    , max_cracks(parameters.max_cracks)
    , cos_threshold(std::cos(parameters.threshold_angle * M_PI / 180.))
    , beta(parameters.shear_factor)
    , initiation(parameters.initiation)
    , mixed_mode(parameters.mixed_mode)
    , integration(parameters.integration)
    , smearing(parameters.smearing)
    , failed_points(parameters.failed)
    , softening(parameters.softening)
    , tracking(parameters.crack_tracking)
    , tracking_radius_in_cells(parameters.tracking_radius)
    , localization(parameters.tracking_localization)
    , parallel_softening(parameters.parallel_softening)
    , M(C[0][0][0][0])
    , bulk(C[0][0][1][1] + 2. * C[0][1][0][1] / dim)
    , compliance(invert(C))
  {
    parameters.check();
    crack_region = parse_region<dim>(parameters.cracking_region,
                                     "smeared cracks: <Cracking region>",
                                     "where cracks may start",
                                     RegionTest::above_one_half);
    // Local stability of the band: the softening slope of T must stay
    // below the band's stiffness M / L for the largest L (= h).
    const double L_max =
      band_width *
      (smearing == SmearingLength::projection ? std::sqrt(double(dim)) : 1.);
    // The steepest part of the branch is its first one.
    const double slope =
      -softening_slope(tau_nf / initial_stiffness(L_max), L_max);
    if (!(slope < M / L_max))
      {
        std::ostringstream message;
        message << "smeared cracks: the softening branch is locally unstable: "
                   "the crack band width h = "
                << band_width
                << " must be smaller than about M / |dT/d delta| = "
                << M / slope * band_width / L_max
                << " (M = lambda + 2 mu = " << M << ", |dT/d delta| = " << slope
                << " the steepest softening slope). Refine the grid or check "
                   "E, tau_nf, G_f.";
        AssertThrow(false, ExcMessage(message.str()));
      }
  }



  template <int dim>
  SmearedCracks<dim>::SmearedCracks(ParameterHandler &prm)
    : SmearedCracks(Parameters::from(prm))
  {
  }



  template <int dim>
  void
  SmearedCracks<dim>::Parameters::add_parameters(ParameterHandler &prm)
  {
    elastic.add_parameters(prm);
    prm.add_parameter("Tensile strength",
                      tensile_strength,
                      "tau_nf: the largest principal stress at which a crack "
                      "starts, and its normal traction then.",
                      Patterns::Double(0.));
    prm.add_parameter("Fracture energy",
                      fracture_energy,
                      "G_f: the energy a crack dissipates per unit area, in "
                      "opening and in slip alike (the area under the "
                      "softening law; delta_0 = 2 G_f / tau_nf for the "
                      "linear law, 3.6 G_f / tau_nf for the bilinear).",
                      Patterns::Double(0.));
    Utils::add_selection<Softening>(
      prm,
      "Softening",
      softening,
      {{"linear", Softening::linear}, {"bilinear", Softening::bilinear}},
      "The softening branch of the cohesive law T(delta), both with the area "
      "G_f. linear: from tau_nf straight to zero at delta_0 = 2 G_f / "
      "tau_nf. bilinear: Petersson's law for concrete (1981; CEB-FIP Model "
      "Code 1990): from tau_nf to tau_nf / 3 at 0.8 G_f / tau_nf, then to "
      "zero at 3.6 G_f / tau_nf; a steep drop and a long tail, as concrete "
      "shows, and lower peak loads than the linear law at the same G_f.");
    prm.add_parameter("Crack band width",
                      crack_band_width,
                      "h: the cell size of the background grid (the width "
                      "of the band of cells that cracks); the smearing "
                      "length of a crack with normal n follows from it "
                      "(<Smearing length>).",
                      Patterns::Double(0.));
    prm.add_parameter("Maximum cracks per point",
                      max_cracks,
                      "At most this many cracks per point (1 to dim).",
                      Patterns::Integer(1, 3));
    prm.add_parameter("Threshold angle",
                      threshold_angle,
                      "A new crack starts only if the principal direction "
                      "makes more than this angle (degrees, 0 to 90) with "
                      "every existing crack normal of the point; otherwise "
                      "the existing cracks carry the load in mixed mode.",
                      Patterns::Double(0., 90.));
    prm.add_parameter("Shear factor",
                      shear_factor,
                      "beta: the weight of the slip in the effective "
                      "separation sqrt(<w>^2 + beta^2 |s|^2); the shear "
                      "strength is beta tau_nf, the energy in pure slip G_f.",
                      Patterns::Double(0.));
    Utils::add_selection<MixedMode>(
      prm,
      "Mixed mode",
      mixed_mode,
      {{"opening", MixedMode::opening},
       {"effective separation", MixedMode::effective_separation}},
      "What drives a crack's damage. opening: the normal opening w; the "
      "shear traction is carried by the same secant stiffness, which falls "
      "with the opening (a shear retention that vanishes at complete "
      "failure); slip alone does not damage. effective separation: "
      "delta = sqrt(<w>^2 + beta^2 |s|^2), so that slip damages too (shear "
      "strength beta tau_nf, energy G_f in pure slip); in the notched "
      "plate Newton's method stalled at the peak with it.");
    Utils::add_selection<SmearingLength>(
      prm,
      "Smearing length",
      smearing,
      {{"mid-plane", SmearingLength::mid_plane},
       {"projection", SmearingLength::projection}},
      "The smearing length L of a crack with normal n in cells of size h. "
      "mid-plane: L = h max_i |n_i|, the cell volume over the area of its "
      "mid-plane normal to n (a band one cell wide along a cell edge, or a "
      "diagonal chain of cells). projection: L = h sum_i |n_i|, the "
      "projection of the cell onto n (Oliver 1989): the width of a band "
      "of cells that share faces, as a crack across the cells of a grid "
      "at an angle opens.");
    Utils::add_selection<DamageIntegration>(
      prm,
      "Damage integration",
      integration,
      {{"implicit", DamageIntegration::implicit},
       {"IMPL-EX", DamageIntegration::impl_ex}},
      "implicit: the damage history of a step follows the trial jumps (the "
      "cohesive law exactly; Newton's method may cycle where many points "
      "sit on the kink between loading and unloading). IMPL-EX (Oliver, "
      "Huespe and Cante 2008): within a step the history is the committed "
      "one plus the increment of the last step, fixed, so that the step is "
      "linear in the jumps; the history is then updated from the converged "
      "jumps. First-order accurate in the step size: the traction may "
      "leave the softening line by one step's change.");
    Utils::add_selection<FailedPoints>(
      prm,
      "Failed points",
      failed,
      {{"keep cracks", FailedPoints::keep_cracks},
       {"no tension", FailedPoints::no_tension}},
      "What a point whose crack has failed completely (delta* >= delta_0, "
      "open) carries from the next step on. keep cracks: its cracks go on "
      "(a fully open crack carries no traction on its own plane, but the "
      "point carries stress along the crack, which locks a band of cells "
      "that crosses the grid at an angle). no tension: the point has "
      "broken apart and carries only a pressure K <tr eps>_- I (K the bulk "
      "modulus), so that a closed crack carries contact but no tension "
      "and no shear crosses the band; the elastic energy it held is "
      "dissipated in the step of the switch. (Keeping the compressive "
      "part in every direction, Miehe's split, still passed shear across "
      "a band at 15 degrees to the grid and locked it.)");
    Utils::add_selection<Initiation>(
      prm,
      "Crack initiation",
      initiation,
      {{"step start", Initiation::step_start},
       {"trial state", Initiation::trial_state}},
      "step start: a crack starts in the step after the one whose converged "
      "stress reached tau_nf (its normal from that stress): the cracks of a "
      "point are fixed within a step, and Newton's method converges where "
      "many points are about to crack; the peak stress overshoots tau_nf "
      "by at most one step's increment. trial state: the trial stress of "
      "each Newton iterate decides (as the decohesion model).");
    prm.add_parameter("Cracking region",
                      cracking_region,
                      "An expression in x, y (and z): points created where "
                      "it is > 0.5 may crack. Default: everywhere.",
                      Patterns::Anything());
    prm.add_parameter(
      "Crack tracking",
      crack_tracking,
      "true: a point may start its first crack only further than <Crack "
      "tracking radius> from every crack, or in the band of cells that the "
      "path of a nearby crack crosses (its line through the crack's path "
      "point, normal to the crack; within half the smearing length of it). "
      "Keeps a crack band straight and one band wide where the grid runs at "
      "an angle to it. Decided after each step for the next one. Not with "
      "a material map. Where cracks may start anywhere, use it with <Mixed "
      "mode> = effective separation and <Shear factor> = 0.5: in a notched "
      "plate at 0-45 degrees to the grid the peak loads then agree within "
      "0.3 % and the work of fracture is 1.02-1.07 G_f times the ligament "
      "(1.05-1.27 with neither); with <Crack tracking localization> = 0.02 "
      "and <Crack-parallel softening> as well, 0.99-1.02, the peaks within "
      "0.8 % of their mean (doc/example_notched_plate.md).");
    prm.add_parameter("Crack tracking radius",
                      tracking_radius,
                      "With <Crack tracking>: the radius, in cell sizes h "
                      "(<Crack band width>), around the path of a crack "
                      "within which points may crack only in its band.",
                      Patterns::Double(0.));
    prm.add_parameter(
      "Crack tracking localization",
      tracking_localization,
      "With <Crack tracking>: once a crack anywhere has dissipated this "
      "fraction of G_f, a point may no longer start a new path away from "
      "the existing ones (further than the radius from all of them); cracks "
      "then grow only in the bands of existing paths. 0 (default): new paths "
      "may start at any time. Around the peak load many points far from the "
      "band reach the tensile strength and crack a little before the band "
      "takes the deformation: in the notched plate at 0-45 degrees to the "
      "grid they dissipated 4-6 % of G_f times the ligament; with 0.02 "
      "0-2.2 %, and the work of fracture was 0.99-1.03 G_f times the "
      "ligament instead of 1.02-1.07 (doc/example_notched_plate.md).",
      Patterns::Double(0., 1.));
    prm.add_parameter(
      "Crack-parallel softening",
      parallel_softening,
      "true: the stress along the plane of a point's crack, P sigma P with "
      "P = I - n n, fades as the crack softens, by the fraction 1 - "
      "T(delta*) / tau_nf, to zero when the crack has failed, where a point "
      "with <Failed points> = no tension breaks apart and would shed it at "
      "once (points with more than one crack keep it). Where a band crosses "
      "the grid at an angle, the grid's staircase of cells compresses or "
      "stretches the band's points along the band; without fading, that "
      "stress grows until a point breaks and is then released in one step: "
      "in the notched plate at 30 degrees to the grid 1.8 % of G_f times "
      "the ligament (doc/example_notched_plate.md). The released energy is "
      "not part of dissipation() (<Control> = dissipation steps by the "
      "cracks' energy). false (default): the stress along the crack plane "
      "follows the elastic law.");
  }



  template <int dim>
  void
  SmearedCracks<dim>::Parameters::check() const
  {
    AssertThrow(max_cracks >= 1 && max_cracks <= dim,
                ExcMessage("smeared cracks: <Maximum cracks per point> = " +
                           std::to_string(max_cracks) + " must be 1 to " +
                           std::to_string(dim) + " in " + std::to_string(dim) +
                           "D."));
    AssertThrow(threshold_angle > 0. && threshold_angle <= 90.,
                ExcMessage("smeared cracks: <Threshold angle> must be above "
                           "0 and at most 90 degrees."));
    AssertThrow(tensile_strength > 0. && fracture_energy > 0.,
                ExcMessage("smeared cracks: <Tensile strength> and <Fracture "
                           "energy> must be positive."));
    AssertThrow(crack_band_width > 0.,
                ExcMessage("smeared cracks: set <Crack band width> to the "
                           "cell size of the background grid."));
    AssertThrow(shear_factor > 0.,
                ExcMessage("smeared cracks: <Shear factor> must be "
                           "positive."));
    AssertThrow(!crack_tracking || tracking_radius >= 1.,
                ExcMessage("smeared cracks: <Crack tracking radius> must be "
                           "at least 1 (cell size): within it, only the "
                           "band of a crack may crack."));
  }



  template <int dim>
  void
  SmearedCracks<dim>::declare_parameters(ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
  }



  template <int dim>
  void
  SmearedCracks<dim>::set_crack_region(
    const std::function<bool(const Point<dim> &)> &region)
  {
    crack_region = region;
  }



  template <int dim>
  std::vector<StateField>
  SmearedCracks<dim>::state_fields() const
  {
    std::vector<StateField> fields = {{allowed_name, 1},
                                      {count_name, 1},
                                      {normals_name, dim * dim},
                                      {jumps_name, dim * dim},
                                      {separation_name, dim},
                                      {separation_increment_name, dim},
                                      {failed_name, 1}};
    if (tracking)
      {
        fields.push_back({anchor_name, dim + 1});
        fields.push_back({band_length_name, 1});
      }
    return fields;
  }



  template <int dim>
  void
  SmearedCracks<dim>::initialize_state(const Point<dim> &x,
                                       ArrayView<double> state) const
  {
    std::fill(state.begin(), state.end(), 0.);
    state[0] = crack_region(x) ? 1. : 0.;
  }



  template <int dim>
  std::vector<StateField>
  SmearedCracks<dim>::output_fields() const
  {
    return {{"crack_count", 1},
            {"separation_over_delta_0", 1},
            {"crack_angle_deg", 1}};
  }



  template <int dim>
  void
  SmearedCracks<dim>::compute_output_fields(const PointState<dim> &point,
                                            ArrayView<double>      values) const
  {
    const Cracks cracks  = read(point.state);
    double       largest = 0.;
    for (unsigned int k = 0; k < cracks.count; ++k)
      largest = std::max(largest, cracks.history[k] / delta_0);
    values[0] = cracks.count;
    values[1] = largest;
    values[2] =
      cracks.count > 0 ?
        std::atan2(cracks.normal[0][1], cracks.normal[0][0]) * 180. / M_PI :
        0.;
  }



  template <int dim>
  typename SmearedCracks<dim>::Cracks
  SmearedCracks<dim>::read(ArrayView<const double> state) const
  {
    Cracks cracks;
    cracks.extrapolated = integration == DamageIntegration::impl_ex;
    cracks.count        = static_cast<unsigned int>(state[1]);
    for (unsigned int k = 0; k < cracks.count; ++k)
      {
        for (unsigned int d = 0; d < dim; ++d)
          {
            cracks.normal[k][d] = state[2 + k * dim + d];
            cracks.jump[k][d]   = state[2 + dim * dim + k * dim + d];
          }
        cracks.history[k]   = state[2 + 2 * dim * dim + k];
        cracks.increment[k] = state[2 + 2 * dim * dim + dim + k];
        cracks.length[k]    = smearing_length(cracks.normal[k]);
      }
    // The first crack's length from its band's direction, once crack
    // tracking has set it.
    if (tracking && cracks.count > 0 && state[band_length_index] > 0.)
      cracks.length[0] = state[band_length_index];
    return cracks;
  }



  template <int dim>
  SymmetricTensor<2, dim>
  SmearedCracks<dim>::stress_of(const SymmetricTensor<2, dim> &eps,
                                const Cracks                  &cracks) const
  {
    SymmetricTensor<2, dim> elastic = eps;
    for (unsigned int k = 0; k < cracks.count; ++k)
      elastic -= symmetrize(outer_product(cracks.jump[k], cracks.normal[k])) /
                 cracks.length[k];
    return C * elastic;
  }



  template <int dim>
  double
  SmearedCracks<dim>::step_history(const Cracks      &cracks,
                                   const unsigned int k) const
  {
    return cracks.history[k] + (cracks.extrapolated ? cracks.increment[k] : 0.);
  }



  template <int dim>
  void
  SmearedCracks<dim>::fade_parallel_stress(const Cracks            &cracks,
                                           SymmetricTensor<2, dim> &sigma) const
  {
    if (!parallel_softening || cracks.count != 1)
      return;
    const double L = cracks.length[0];
    const double h = step_history(cracks, 0);
    if (h <= tau_nf / initial_stiffness(L))
      return;
    const double         omega = 1. - cohesive_traction(h, L) / tau_nf;
    const Tensor<2, dim> P     = unit_symmetric_tensor<dim>() -
                             outer_product(cracks.normal[0], cracks.normal[0]);
    sigma -= omega * symmetrize(P * Tensor<2, dim>(sigma) * P);
  }



  template <int dim>
  unsigned int
  SmearedCracks<dim>::softening_corners(
    const double                          L,
    std::array<std::array<double, 2>, 3> &corners) const
  {
    const double delta_e = tau_nf / initial_stiffness(L);
    corners[0]           = {{delta_e, tau_nf}};
    if (softening == Softening::linear)
      {
        corners[1] = {{delta_0, 0.}};
        return 2;
      }
    // The kink of Petersson's law, moved by delta_e / 3 so that the area
    // under T, initial branch included, is G_f exactly:
    // 1/2 tau delta_e + 2/3 tau (delta_k - delta_e) + 1/6 tau (delta_0 -
    // delta_k) = G_f with delta_0 = 3.6 G_f / tau.
    corners[1] = {{0.8 * G_f / tau_nf + delta_e / 3., tau_nf / 3.}};
    corners[2] = {{delta_0, 0.}};
    return 3;
  }



  template <int dim>
  double
  SmearedCracks<dim>::cohesive_traction(const double delta,
                                        const double L) const
  {
    std::array<std::array<double, 2>, 3> c;
    const unsigned int                   n = softening_corners(L, c);
    if (delta <= c[0][0])
      return initial_stiffness(L) * delta;
    for (unsigned int i = 1; i < n; ++i)
      if (delta < c[i][0])
        return c[i - 1][1] + (c[i][1] - c[i - 1][1]) * (delta - c[i - 1][0]) /
                               (c[i][0] - c[i - 1][0]);
    return 0.;
  }



  template <int dim>
  double
  SmearedCracks<dim>::softening_slope(const double delta, const double L) const
  {
    std::array<std::array<double, 2>, 3> c;
    const unsigned int                   n = softening_corners(L, c);
    for (unsigned int i = 1; i < n; ++i)
      if (delta < c[i][0] || i + 1 == n)
        return (c[i][1] - c[i - 1][1]) / (c[i][0] - c[i - 1][0]);
    return 0.;
  }



  template <int dim>
  double
  SmearedCracks<dim>::initial_stiffness(const double L) const
  {
    return 100. * M / L;
  }



  template <int dim>
  double
  SmearedCracks<dim>::contact_stiffness(const double L) const
  {
    return 1000. * M / L;
  }



  template <int dim>
  double
  SmearedCracks<dim>::secant(const double delta_star, const double L) const
  {
    const double K0 = initial_stiffness(L);
    return delta_star <= tau_nf / K0 ?
             K0 :
             cohesive_traction(delta_star, L) / delta_star;
  }



  template <int dim>
  double
  SmearedCracks<dim>::shear_weight() const
  {
    return mixed_mode == MixedMode::opening ? 1. : beta * beta;
  }



  template <int dim>
  double
  SmearedCracks<dim>::dissipated_energy(const double delta,
                                        const double L) const
  {
    std::array<std::array<double, 2>, 3> c;
    const unsigned int                   n = softening_corners(L, c);
    if (delta <= c[0][0])
      return 0.;
    // The work of T up to delta (trapezoids over the corners passed),
    // minus what unloading along the secant gives back.
    double work = 0.5 * c[0][0] * c[0][1];
    for (unsigned int i = 1; i < n; ++i)
      {
        const double end = std::min(delta, c[i][0]);
        work +=
          0.5 * (c[i - 1][1] + cohesive_traction(end, L)) * (end - c[i - 1][0]);
        if (delta <= c[i][0])
          break;
      }
    return work - 0.5 * cohesive_traction(delta, L) * delta;
  }



  template <int dim>
  Tensor<1, dim>
  SmearedCracks<dim>::traction(const Cracks         &cracks,
                               const unsigned int    k,
                               const Tensor<1, dim> &jump,
                               Tensor<2, dim>       *derivative) const
  {
    const Tensor<1, dim> &n     = cracks.normal[k];
    const double          L     = cracks.length[k];
    const double          w     = jump * n;
    const double          w_pos = std::max(w, 0.);
    const Tensor<1, dim>  s     = jump - w * n;
    // The damage driver: the opening, or the effective separation.
    const bool   by_opening = mixed_mode == MixedMode::opening;
    const double delta =
      by_opening ? w_pos :
                   std::sqrt(w_pos * w_pos + beta * beta * s.norm_square());
    // IMPL-EX: the history of the step is extrapolated from the last one
    // and fixed, so that the traction is linear in the jump within a step.
    const bool   loading    = !cracks.extrapolated && delta > cracks.history[k];
    const double delta_star = loading ? delta : step_history(cracks, k);
    const double K0         = initial_stiffness(L);
    const double Kc         = contact_stiffness(L);
    // The secant q = T(delta*) / delta* (K0 on the initial branch).
    const double q = secant(delta_star, L);
    // The shear weight: beta^2 with the effective separation (so that the
    // traction is the gradient of a potential in delta), 1 when the
    // opening drives the damage (the shear traction q s: the secant shear
    // stiffness falls with the normal damage).
    const double         b2 = shear_weight();
    const Tensor<1, dim> g  = w_pos * n + b2 * s;
    Tensor<1, dim>       t  = q * g + Kc * std::min(w, 0.) * n;
    if (derivative != nullptr)
      {
        const Tensor<2, dim> nn = outer_product(n, n);
        Tensor<2, dim>       D  = q * ((w > 0. ? 1. : 0.) * nn +
                                b2 * (unit_symmetric_tensor<dim>() - nn)) +
                           (w < 0. ? Kc : 0.) * nn;
        // On the softening branch while loading, q = T / delta falls with
        // delta: dq/d delta = (T' delta - T) / delta^2, and d delta / du =
        // g / delta (effective separation) or n (opening).
        const double delta_e = tau_nf / K0;
        if (loading && delta > delta_e && delta < delta_0)
          {
            const double dq = (softening_slope(delta, L) * delta -
                               cohesive_traction(delta, L)) /
                              (delta * delta);
            D += dq * outer_product(g, by_opening ? n : g / delta);
          }
        *derivative = D;
      }
    return t;
  }



  template <int dim>
  bool
  SmearedCracks<dim>::solve_jumps(const SymmetricTensor<2, dim> &eps,
                                  Cracks                        &cracks) const
  {
    const unsigned int m = cracks.count, n_unknowns = m * dim;
    if (m == 0)
      return true;
    // The couplings -G(n_k, n_j) / L_j do not depend on the jumps.
    std::array<Tensor<2, dim>, dim * dim> G;
    for (unsigned int k = 0; k < m; ++k)
      for (unsigned int j = 0; j < m; ++j)
        G[k * dim + j] =
          coupling(C, cracks.normal[k], cracks.normal[j]) / cracks.length[j];

    const auto residual = [&](const Cracks                     &state,
                              std::array<double, max_unknowns> &r) {
      const SymmetricTensor<2, dim> sigma = stress_of(eps, state);
      double                        norm  = 0.;
      for (unsigned int k = 0; k < m; ++k)
        {
          const Tensor<1, dim> rk = sigma * state.normal[k] -
                                    traction(state, k, state.jump[k], nullptr);
          for (unsigned int a = 0; a < dim; ++a)
            {
              r[k * dim + a] = rk[a];
              norm += rk[a] * rk[a];
            }
        }
      return std::sqrt(norm);
    };

    std::array<double, max_unknowns> r{};
    double                           norm      = residual(cracks, r);
    const double                     tolerance = 1e-14 * tau_nf;
    for (unsigned int iteration = 0; iteration < 60; ++iteration)
      {
        if (norm <= tolerance)
          return true;
        // J = d r / d u: -G_kj - delta_kj dt_k/du_k.
        std::array<double, max_unknowns * max_unknowns> J{};
        for (unsigned int k = 0; k < m; ++k)
          {
            Tensor<2, dim> Dt;
            traction(cracks, k, cracks.jump[k], &Dt);
            for (unsigned int j = 0; j < m; ++j)
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  J[(k * dim + a) * n_unknowns + j * dim + b] =
                    -G[k * dim + j][a][b] - (k == j ? Dt[a][b] : 0.);
          }
        std::array<double, max_unknowns> step = r;
        if (!solve_dense(J, step, n_unknowns))
          return false;
        // Backtracking on |r|: the cohesive law has kinks (loading and
        // unloading, contact).
        double lambda     = 1.;
        Cracks trial      = cracks;
        double trial_norm = norm;
        for (unsigned int halving = 0; halving < 12; ++halving, lambda *= 0.5)
          {
            trial = cracks;
            for (unsigned int k = 0; k < m; ++k)
              for (unsigned int a = 0; a < dim; ++a)
                trial.jump[k][a] -= lambda * step[k * dim + a];
            std::array<double, max_unknowns> trial_r{};
            trial_norm = residual(trial, trial_r);
            if (trial_norm < norm)
              {
                r = trial_r;
                break;
              }
          }
        if (!(trial_norm < norm))
          break;
        cracks = trial;
        norm   = trial_norm;
      }
    if (norm <= 1e-9 * tau_nf)
      return true;

    // With IMPL-EX the law is piecewise linear: per crack, open (secant q
    // across) or in contact (the penalty K_c across). Where Newton's
    // method cycles between the two (a crack that has almost failed, with
    // q near zero, closing), try every combination and keep the one whose
    // openings have the signs it assumed.
    if (!cracks.extrapolated)
      return false;
    const SymmetricTensor<2, dim> C_eps = C * eps;
    for (unsigned int mask = 0; mask < (1u << m); ++mask)
      {
        std::array<double, max_unknowns * max_unknowns> A{};
        std::array<double, max_unknowns>                u{};
        for (unsigned int k = 0; k < m; ++k)
          {
            const Tensor<1, dim> &n          = cracks.normal[k];
            const bool            in_contact = (mask >> k) & 1u;
            // The secant of traction(): its derivative with the opening
            // assumed positive (open) or negative (contact).
            Tensor<1, dim> probe = n;
            if (in_contact)
              probe = -n;
            Tensor<2, dim> S;
            Cracks         at = cracks;
            at.jump[k]        = 1e-30 * probe;
            traction(at, k, at.jump[k], &S);
            const Tensor<1, dim> t = C_eps * n;
            for (unsigned int a = 0; a < dim; ++a)
              {
                u[k * dim + a] = t[a];
                for (unsigned int j = 0; j < m; ++j)
                  for (unsigned int b = 0; b < dim; ++b)
                    A[(k * dim + a) * n_unknowns + j * dim + b] =
                      G[k * dim + j][a][b] + (k == j ? S[a][b] : 0.);
              }
          }
        if (!solve_dense(A, u, n_unknowns))
          continue;
        Cracks candidate  = cracks;
        bool   consistent = true;
        for (unsigned int k = 0; k < m; ++k)
          {
            for (unsigned int a = 0; a < dim; ++a)
              candidate.jump[k][a] = u[k * dim + a];
            const double w          = candidate.jump[k] * cracks.normal[k];
            const bool   in_contact = (mask >> k) & 1u;
            if ((in_contact && w > 0.) || (!in_contact && w < 0.))
              consistent = false;
          }
        std::array<double, max_unknowns> check{};
        if (consistent && residual(candidate, check) <= 1e-9 * tau_nf)
          {
            cracks = candidate;
            return true;
          }
      }
    return false;
  }



  template <int dim>
  void
  SmearedCracks<dim>::update_stress(
    const PointState<dim>         &old,
    const SymmetricTensor<2, dim> &strain_increment,
    SymmetricTensor<2, dim>       &stress,
    ArrayView<double>              new_state) const
  {
    std::copy(old.state.begin(), old.state.end(), new_state.begin());
    const SymmetricTensor<2, dim> eps = old.strain + strain_increment;
    if (old.state[failed_index] > 0.)
      {
        stress                  = no_tension_stress(eps);
        new_state[failed_index] = 2.;
        return;
      }
    Cracks cracks = read(old.state);

    // New cracks: where the largest principal stress reaches tau_nf along a
    // direction far enough from the existing normals. By default the
    // committed stress of the start of the step decides (the set of cracks
    // is then fixed within a step and the residual is a smooth function of
    // the increment, which Newton's method needs where many points are
    // about to crack); with trial-state initiation the trial stress does.
    const bool allowed          = old.state[0] > 0.;
    const auto add_crack_if_due = [&](const SymmetricTensor<2, dim> &sigma) {
      if (!allowed || cracks.count >= max_cracks)
        return false;
      // Eigenvalues are cheap; eigenvectors only where a crack may start.
      if (eigenvalues(sigma)[0] < tau_nf)
        return false;
      const Tensor<1, dim> v = eigenvectors(sigma)[0].second;
      for (unsigned int k = 0; k < cracks.count; ++k)
        if (std::abs(v * cracks.normal[k]) >= cos_threshold)
          return false;
      const unsigned int k = cracks.count++;
      cracks.normal[k]     = v;
      cracks.jump[k]       = Tensor<1, dim>();
      cracks.history[k]    = 0.;
      cracks.length[k]     = smearing_length(v);
      return true;
    };
    if (initiation == Initiation::step_start)
      add_crack_if_due(old.stress);
    bool solved = solve_jumps(eps, cracks);
    stress      = stress_of(eps, cracks);
    if (initiation == Initiation::trial_state)
      while (solved && add_crack_if_due(stress))
        {
          solved = solve_jumps(eps, cracks);
          stress = stress_of(eps, cracks);
        }
    if (!solved)
      {
        // No equilibrium of the cracks found: a residual that is not a
        // number makes Newton back off (or cut the step).
        stress = std::numeric_limits<double>::quiet_NaN() *
                 unit_symmetric_tensor<dim>();
        return;
      }
    fade_parallel_stress(cracks, stress);

    // IMPL-EX's implicit stage (Oliver, Huespe and Cante 2008): the
    // stress of the step is that of the extrapolated history, but the
    // history itself follows the implicit law at the step's strain. Taken
    // from the jumps of the extrapolated secant instead, a history that
    // grew in the last step grows on, as the softer secant opens the crack
    // further.
    if (cracks.extrapolated)
      {
        Cracks implicit       = cracks;
        implicit.extrapolated = false;
        if (solve_jumps(eps, implicit))
          cracks.jump = implicit.jump;
      }

    new_state[1] = cracks.count;
    for (unsigned int k = 0; k < cracks.count; ++k)
      {
        const Tensor<1, dim> &n     = cracks.normal[k];
        const double          w     = std::max(cracks.jump[k] * n, 0.);
        const Tensor<1, dim>  s     = cracks.jump[k] - (cracks.jump[k] * n) * n;
        const double          delta = mixed_mode == MixedMode::opening ?
                                        w :
                                        std::sqrt(w * w + beta * beta * s.norm_square());
        for (unsigned int d = 0; d < dim; ++d)
          {
            new_state[2 + k * dim + d]             = n[d];
            new_state[2 + dim * dim + k * dim + d] = cracks.jump[k][d];
          }
        const double history             = std::max(cracks.history[k], delta);
        new_state[2 + 2 * dim * dim + k] = history;
        new_state[2 + 2 * dim * dim + dim + k] = history - cracks.history[k];
        // A crack that failed completely while open breaks the point apart
        // from the next step on (the switch is not part of this step's
        // residual, whose Newton iteration would otherwise jump between
        // the two laws).
        if (failed_points == FailedPoints::no_tension && history >= delta_0 &&
            cracks.jump[k] * n > 0.)
          new_state[failed_index] = 1.;
      }
  }



  template <int dim>
  SymmetricTensor<2, dim>
  SmearedCracks<dim>::no_tension_stress(const SymmetricTensor<2, dim> &eps,
                                        SymmetricTensor<4, dim> *tangent) const
  {
    const double trace = std::min(dealii::trace(eps), 0.);
    if (tangent != nullptr)
      *tangent =
        (trace < 0. ? bulk : 0.) * outer_product(unit_symmetric_tensor<dim>(),
                                                 unit_symmetric_tensor<dim>());
    return bulk * trace * unit_symmetric_tensor<dim>();
  }



  template <int dim>
  double
  SmearedCracks<dim>::no_tension_energy(
    const SymmetricTensor<2, dim> &eps) const
  {
    return 0.5 * bulk * std::pow(std::min(trace(eps), 0.), 2);
  }



  template <int dim>
  SymmetricTensor<4, dim>
  SmearedCracks<dim>::tangent(const PointState<dim> &old) const
  {
    if (old.state[failed_index] > 0.)
      {
        // A failed point under tension has no stiffness; the preconditioner
        // keeps 1e-6 of the elastic one so that it stays invertible where a
        // node is held by failed points only.
        SymmetricTensor<4, dim> result;
        no_tension_stress(old.strain, &result);
        return result + 1e-6 * C;
      }
    const Cracks cracks = read(old.state);
    if (cracks.count == 0)
      return C;
    const unsigned int m = cracks.count, n_unknowns = m * dim;
    // The condensed system (G + S) du = (C : E) n of the jumps for a strain
    // variation E, with S_k the secant of crack k at its committed state;
    // the matrix does not depend on E.
    std::array<double, max_unknowns * max_unknowns> matrix{};
    for (unsigned int k = 0; k < m; ++k)
      {
        const Tensor<1, dim> &n    = cracks.normal[k];
        const double          L    = cracks.length[k];
        const double          q    = secant(step_history(cracks, k), L);
        const bool            open = cracks.jump[k] * n >= 0.;
        const Tensor<2, dim>  nn   = outer_product(n, n);
        const Tensor<2, dim>  S =
          q * (shear_weight() * (unit_symmetric_tensor<dim>() - nn)) +
          (open ? q : contact_stiffness(L)) * nn;
        for (unsigned int j = 0; j < m; ++j)
          {
            const Tensor<2, dim> G =
              coupling(C, n, cracks.normal[j]) / cracks.length[j];
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int l = 0; l < dim; ++l)
                matrix[(k * dim + i) * n_unknowns + j * dim + l] =
                  G[i][l] + (k == j ? S[i][l] : 0.);
          }
      }
    SymmetricTensor<4, dim> result;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = a; b < dim; ++b)
        {
          SymmetricTensor<2, dim> E;
          E[a][b]                                           = 1.;
          const SymmetricTensor<2, dim>                  CE = C * E;
          std::array<double, max_unknowns *max_unknowns> A  = matrix;
          std::array<double, max_unknowns>               rhs{};
          for (unsigned int k = 0; k < m; ++k)
            {
              const Tensor<1, dim> t = CE * cracks.normal[k];
              for (unsigned int i = 0; i < dim; ++i)
                rhs[k * dim + i] = t[i];
            }
          Cracks response = cracks;
          if (solve_dense(A, rhs, n_unknowns))
            for (unsigned int k = 0; k < m; ++k)
              for (unsigned int i = 0; i < dim; ++i)
                response.jump[k][i] = rhs[k * dim + i];
          SymmetricTensor<2, dim> d_sigma = stress_of(E, response);
          fade_parallel_stress(response, d_sigma);
          const double factor = (a == b) ? 1. : 0.5;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              result[i][j][a][b] = factor * d_sigma[i][j];
        }
    return result;
  }



  template <int dim>
  double
  SmearedCracks<dim>::dissipation(const PointState<dim>  &old,
                                  ArrayView<const double> new_state) const
  {
    // The step in which a point breaks apart releases the elastic energy
    // that its cracks' law held beyond what the compressive part keeps;
    // a failed point is elastic (in compression) thereafter.
    if (old.state[failed_index] > 1.5)
      return 0.;
    if (old.state[failed_index] > 0.)
      return std::max(0.5 * old.stress * (compliance * old.stress) -
                        no_tension_energy(old.strain),
                      0.);
    const Cracks before = read(old.state);
    const Cracks after  = read(new_state);
    double       result = 0.;
    for (unsigned int k = 0; k < after.count; ++k)
      {
        const double L        = after.length[k];
        const double previous = k < before.count ? before.history[k] : 0.;
        result += (dissipated_energy(after.history[k], L) -
                   dissipated_energy(previous, L)) /
                  L;
        // With the opening as the damage driver the shear secant falls
        // with the normal damage and releases (q_old - q_new) |s|^2 / 2.
        if (mixed_mode == MixedMode::opening && after.history[k] > previous)
          {
            const Tensor<1, dim> &n = after.normal[k];
            const Tensor<1, dim>  s = after.jump[k] - (after.jump[k] * n) * n;
            result += 0.5 *
                      (secant(previous, L) - secant(after.history[k], L)) *
                      s.norm_square() / L;
          }
      }
    return result;
  }



  template <int dim>
  double
  SmearedCracks<dim>::critical_separation() const
  {
    return delta_0;
  }



  template <int dim>
  unsigned int
  SmearedCracks<dim>::crack_summaries(
    ArrayView<const double>        state,
    std::array<CrackSummary, dim> &summaries) const
  {
    const Cracks cracks = read(state);
    for (unsigned int k = 0; k < cracks.count; ++k)
      summaries[k] = {cracks.normal[k],
                      cracks.length[k],
                      dissipated_energy(cracks.history[k], cracks.length[k])};
    return cracks.count;
  }



  template <int dim>
  double
  SmearedCracks<dim>::dissipated_over_fracture_energy(
    ArrayView<const double> state) const
  {
    const Cracks cracks = read(state);
    double       result = 0.;
    for (unsigned int k = 0; k < cracks.count; ++k)
      result += dissipated_energy(cracks.history[k], cracks.length[k]);
    return result / G_f;
  }



  template <int dim>
  double
  SmearedCracks<dim>::fracture_energy() const
  {
    return G_f;
  }



  template <int dim>
  double
  SmearedCracks<dim>::smearing_length(const Tensor<1, dim> &n) const
  {
    double largest = 0., sum = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        largest = std::max(largest, std::abs(n[d]));
        sum += std::abs(n[d]);
      }
    return band_width *
           (smearing == SmearingLength::projection ? sum : largest);
  }



  template class SmearedCracks<2>;
  template class SmearedCracks<3>;

  QSMPM_REGISTER_CONSTITUTIVE_MODEL(
    SmearedCracks,
    "smeared cracks",
    "Up to dim smeared cracks per point at any angle (normal from the "
    "principal stress at initiation, a threshold angle between cracks), "
    "mixed-mode damage-type cohesive law with linear softening, closing and "
    "re-opening, one fracture energy: E, nu, tau_nf, G_f, crack band width, "
    "cracking region (default everywhere).")
} // namespace qsmpm
