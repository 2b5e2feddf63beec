// LoadStepper with increment growth (Load stepping/Increment growth factor):
//
// - off (g = 1): every step takes the nominal increment final / K;
// - g = 2 from |t| >= 4 (nominal 1): steps of 1 up to t = 4, then 2, 4, 8,
//   capped at the maximum increment 10, and the final value hit exactly;
// - a cut-back in the growth stage halves the increment, which then grows
//   again from the halved value;
// - a negative final load factor grows in the same way with its sign.
#include "tests.h"

#include <qsmpm/loading/load_stepper.h>

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
}
