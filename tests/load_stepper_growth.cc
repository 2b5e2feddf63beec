// LoadStepper with increment growth (Load stepping/Increment growth factor):
//
// - off (g = 1): every step takes the nominal increment final / K;
// - g = 2 from |t| >= 4 (nominal 1): steps of 1 up to t = 4, then 2, 4, 8,
//   capped at the maximum increment 10, and the final value hit exactly;
// - a cut-back in the growth stage halves the increment, which then grows
//   again from the halved value;
// - a negative final load factor grows in the same way with its sign.
//
// With path following (Control = dissipation):
// - after a step back (load factor decreasing), a step at the forward limit
//   is allowed only as the last cut-back, and after a forward step at once;
// - that state and the peak force (the reference of the guard against a
//   reversed load) survive save()/load() (a checkpoint): a resumed run must
//   take the same steps as an uninterrupted one;
// - cut-backs halve the dissipation target and the forward limit but not
//   the backward range (10 x the uncut limit), which a snap-back needs
//   however small the energy of the step.
#include "tests.h"

#include <qsmpm/loading/load_stepper.h>
#include <sstream>

using namespace qsmpm;

namespace
{
  // The load factors of the accepted steps until the end.
  std::vector<double>
  run(const LoadStepper::Parameters &parameters, const unsigned int reject_at)
  {
    LoadStepper         stepper(parameters);
    std::vector<double> t;
    while (!stepper.finished() && t.size() < 100)
      {
        if (t.size() + 1 == reject_at && stepper.n_cut_backs() == 0)
          {
            stepper.reject("test");
            continue;
          }
        stepper.accept();
        t.push_back(stepper.current());
      }
    return t;
  }

  bool
  equal(const std::vector<double> &a, const std::vector<double> &b)
  {
    if (a.size() != b.size())
      return false;
    for (unsigned int i = 0; i < a.size(); ++i)
      if (std::abs(a[i] - b[i]) > 1e-12 * std::max(1., std::abs(b[i])))
        return false;
    return true;
  }
} // namespace

int
main()
{
  initlog();

  LoadStepper::Parameters parameters;
  parameters.n_steps           = 40;
  parameters.final_load_factor = 40.;
  parameters.max_cut_backs     = 2;
  std::vector<double> off;
  for (unsigned int i = 1; i <= 40; ++i)
    off.push_back(i);
  check_that("growth off: 40 steps of the nominal increment",
             equal(run(parameters, 0), off));

  parameters.growth_factor = 2.;
  parameters.growth_start  = 4.;
  parameters.max_increment = 10.;
  check_that("growth 2 from t = 4, at most 10: 1 2 3 4 6 10 18 28 38 40",
             equal(run(parameters, 0), {1, 2, 3, 4, 6, 10, 18, 28, 38, 40}));

  // Step 6 (6 -> 10) is cut back to 6 -> 8, then grows from 2 again.
  check_that("cut-back in the growth stage: 1 2 3 4 6 8 12 20 30 40",
             equal(run(parameters, 6), {1, 2, 3, 4, 6, 8, 12, 20, 30, 40}));

  parameters.final_load_factor = -40.;
  check_that("negative load: -1 -2 -3 -4 -6 -10 -18 -28 -38 -40",
             equal(run(parameters, 0),
                   {-1, -2, -3, -4, -6, -10, -18, -28, -38, -40}));

  LoadStepper::Parameters following;
  following.control               = "dissipation";
  following.dissipation_increment = 0.02;
  following.max_increment         = 1e-4;
  following.n_steps               = 10;
  following.final_load_factor     = 1e-3;
  following.max_cut_backs         = 3;
  LoadStepper stepper(following);
  stepper.accept(2e-4, 1.);
  check_that("path following, after a forward step: limit allowed",
             stepper.allow_limit());
  stepper.accept(1.5e-4, 0.5);
  check_that("after a step back: limit not allowed", !stepper.allow_limit());
  std::stringstream checkpoint;
  stepper.save(checkpoint);
  LoadStepper resumed(following);
  resumed.load(checkpoint);
  check_that("after a step back, saved and loaded: limit not allowed",
             !resumed.allow_limit() && resumed.current() == 1.5e-4 &&
               resumed.force() == 0.5);
  check_that("peak force (the sign guard's reference) 1 before and after "
             "saving",
             stepper.peak_force() == 1. && resumed.peak_force() == 1.);
  for (unsigned int i = 0; i < following.max_cut_backs; ++i)
    resumed.reject("test");
  check_that("... allowed at the last cut-back", resumed.allow_limit());
  check_that("3 cut-backs: dissipation and forward limit / 8, backward "
             "range 10 x 1e-4",
             std::abs(resumed.constraint_target() - 0.02 / 8.) < 1e-15 &&
               std::abs(resumed.increment_limit() - 1e-4 / 8.) < 1e-15 &&
               std::abs(resumed.backward_limit() - 1e-3) < 1e-15);
}
