#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <iomanip>
#include <istream>
#include <limits>
#include <ostream>
#include <qsmpm/loading/load_stepper.h>
#include <sstream>

namespace qsmpm
{
  void
  LoadStepper::Parameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Load stepping");
    {
      prm.add_parameter("Number of steps",
                        n_steps,
                        "K: the load factor goes from 0 to its final value "
                        "in K equal increments.",
                        Patterns::Integer(1));
      prm.add_parameter("Final load factor",
                        final_load_factor,
                        "The load factor t at the end of the run; it is the "
                        "time variable t of all boundary and load functions.",
                        Patterns::Double());
      prm.add_parameter("Maximum cut-backs",
                        max_cut_backs,
                        "How often in a row a step that did not converge is "
                        "retried with a smaller increment before the run "
                        "stops.",
                        Patterns::Integer(0, 30));
      prm.add_parameter("Cut-back factor",
                        cut_back_factor,
                        "The increment is multiplied by this after a failed "
                        "attempt.",
                        Patterns::Double(0.01, 0.99));
      prm.add_parameter("Increment growth factor",
                        growth_factor,
                        "g: once |t| has reached <Growth from load factor>, "
                        "each accepted step multiplies the increment by g "
                        "(at least the nominal increment, at most <Maximum "
                        "increment>). 1: off, every step takes the nominal "
                        "increment final / K.",
                        Patterns::Double(1., 10.));
      prm.add_parameter("Growth from load factor",
                        growth_start,
                        "|t| from which the increment grows by <Increment "
                        "growth factor>.",
                        Patterns::Double(0.));
      prm.add_parameter("Maximum increment",
                        max_increment,
                        "Largest |increment| reached by growth; 0: no "
                        "limit but the final load factor. With path "
                        "following (<Control> = dissipation or opening): "
                        "the largest increment of a step (a step that "
                        "cannot meet its constraint below it takes it under "
                        "displacement control); 0: the nominal increment "
                        "final / K.",
                        Patterns::Double(0.));
      prm.add_parameter(
        "Control",
        control,
        "displacement: the load factor of every step is prescribed (the "
        "paper's method; snap-backs are jumped over). dissipation: path "
        "following, the load factor of a step is an unknown and the "
        "material points dissipate <Dissipation increment> in each step "
        "(Gutierrez 2004; Verhoosel, Remmers and Gutierrez 2009), so that "
        "snap-backs are traced; steps that would need more than <Maximum "
        "increment> are displacement-controlled. Needs a model that "
        "computes its dissipation (decohesion). opening: path following "
        "in which each step opens the <Opening gauge> by <Opening "
        "increment> (crack-mouth opening displacement control). Both need "
        "displacement conditions proportional to t and no other loads.",
        Patterns::Selection("displacement|dissipation|opening"));
      prm.add_parameter("Dissipation increment",
                        dissipation_increment,
                        "With <Control> = dissipation: the energy the "
                        "material points dissipate in each step (in 2D per "
                        "unit thickness, J/m).",
                        Patterns::Double(0.));
      prm.add_parameter("Opening increment",
                        opening_increment,
                        "With <Control> = opening: the increase of the "
                        "gauge's opening in each step (a length).",
                        Patterns::Double(0.));
      prm.add_parameter(
        "Opening gauge",
        opening_gauge,
        "With <Control> = opening: two positions x_a; x_b (dim "
        "coordinates each, separated by ';', e.g. -0.01,0.3; 0.01,0.3). The "
        "gauge is the pair of material points that were nearest to them "
        "at the start of the run, and its opening is the increase of "
        "(u_b - u_a) . (x_b - x_a)/|x_b - x_a|, u the points' "
        "displacements.",
        Patterns::Anything());
    }
    prm.leave_subsection();
  }



  LoadStepper::LoadStepper(const Parameters &parameters)
    : parameters(parameters)
    , nominal_increment(parameters.final_load_factor / parameters.n_steps)
    , increment(nominal_increment)
  {
    AssertThrow(parameters.n_steps > 0,
                ExcMessage("Load stepping: <Number of steps> must be > 0."));
    AssertThrow(parameters.growth_factor >= 1.,
                ExcMessage("Load stepping: <Increment growth factor> must be "
                           ">= 1."));
    control_type = parse_control(parameters.control);
    if (path_following())
      {
        const std::string &name       = parameters.control;
        const bool         dissipates = control_type == Control::dissipation;
        const std::string  entry =
          dissipates ? "Dissipation increment" : "Opening increment";
        nominal_target = dissipates ? parameters.dissipation_increment :
                                      parameters.opening_increment;
        AssertThrow(nominal_target > 0.,
                    ExcMessage("Load stepping: <" + entry +
                               "> must be > 0 with Control = " + name + "."));
        AssertThrow(parameters.growth_factor == 1.,
                    ExcMessage("Load stepping: <Increment growth factor> "
                               "must be 1 with Control = " +
                               name +
                               " (the step size follows from the "
                               "constraint)."));
        AssertThrow(parameters.final_load_factor > 0.,
                    ExcMessage("Load stepping: <Final load factor> must be "
                               "> 0 with Control = " +
                               name + "."));
        increment    = increment_cap();
        target_value = nominal_target;
      }
  }



  const LoadStepper::Parameters &
  LoadStepper::get_parameters() const
  {
    return parameters;
  }



  LoadStepper::Control
  LoadStepper::parse_control(const std::string &name)
  {
    if (name == "displacement")
      return Control::displacement;
    if (name == "dissipation")
      return Control::dissipation;
    AssertThrow(name == "opening",
                ExcMessage("Load stepping: unknown <Control> = " + name + "."));
    return Control::opening;
  }



  std::string
  LoadStepper::to_string(const Control control)
  {
    switch (control)
      {
        case Control::displacement:
          return "displacement";
        case Control::dissipation:
          return "dissipation";
        default:
          return "opening";
      }
  }



  bool
  LoadStepper::path_following() const
  {
    return control_type != Control::displacement;
  }



  double
  LoadStepper::increment_cap() const
  {
    return parameters.max_increment > 0. ? parameters.max_increment :
                                           nominal_increment;
  }



  LoadStepper::Control
  LoadStepper::control() const
  {
    return control_type;
  }



  double
  LoadStepper::constraint_target() const
  {
    return target_value;
  }



  double
  LoadStepper::increment_limit() const
  {
    return increment;
  }



  double
  LoadStepper::backward_limit() const
  {
    return 10. * increment_cap();
  }



  bool
  LoadStepper::allow_limit() const
  {
    return !went_back || cut_backs == parameters.max_cut_backs;
  }



  double
  LoadStepper::peak_force() const
  {
    return F_peak;
  }



  double
  LoadStepper::force() const
  {
    return F;
  }



  void
  LoadStepper::accept(const double t_new, const double force_new)
  {
    Assert(path_following(), ExcInternalError());
    went_back = t_new < t;
    t         = t_new;
    if (std::abs(force_new) > std::abs(F_peak))
      F_peak = force_new;
    F = force_new;
    ++n_steps;
    cut_backs    = 0;
    increment    = increment_cap();
    target_value = nominal_target;
  }



  bool
  LoadStepper::finished() const
  {
    // With path following the load factor is not prescribed; the run ends
    // once it has reached the final value.
    if (path_following())
      return t >= parameters.final_load_factor * (1. - 1e-12);
    return std::abs(t - parameters.final_load_factor) <=
           1e-12 * std::abs(parameters.final_load_factor);
  }



  double
  LoadStepper::current() const
  {
    return t;
  }



  double
  LoadStepper::target() const
  {
    // Do not overshoot the final value, and do not leave a sliver behind.
    const double remaining = parameters.final_load_factor - t;
    if (std::abs(remaining) <= 1.000001 * std::abs(increment))
      return parameters.final_load_factor;
    return t + increment;
  }



  unsigned int
  LoadStepper::step() const
  {
    return n_steps;
  }



  void
  LoadStepper::accept()
  {
    t = target();
    ++n_steps;
    cut_backs = 0;
    if (parameters.growth_factor > 1. && std::abs(t) >= parameters.growth_start)
      {
        // Grow from the increment just taken (which a cut-back may have
        // lowered), not below the nominal one and not above the limit.
        double magnitude =
          std::max(std::abs(nominal_increment),
                   parameters.growth_factor * std::abs(increment));
        if (parameters.max_increment > 0.)
          magnitude = std::min(magnitude, parameters.max_increment);
        increment = std::copysign(magnitude, nominal_increment);
      }
    else
      increment = nominal_increment;
  }



  void
  LoadStepper::reject(const std::string &reason)
  {
    if (cut_backs >= parameters.max_cut_backs)
      {
        std::ostringstream message;
        message << "Load step " << n_steps + 1 << " (load factor " << t
                << " -> " << target() << ") did not converge: " << reason
                << ". It was cut back " << cut_backs
                << " times already (Load stepping/Maximum cut-backs = "
                << parameters.max_cut_backs
                << "). Nothing of this step was written as converged.";
        AssertThrow(false, ExcMessage(message.str()));
      }
    ++cut_backs;
    increment *= parameters.cut_back_factor;
    target_value *= parameters.cut_back_factor;
  }



  unsigned int
  LoadStepper::n_cut_backs() const
  {
    return cut_backs;
  }



  // A checkpoint is written between steps, where the count of cut-backs is
  // zero. The increment must be kept as well: with growth (or after a
  // cut-back) it is not the nominal one, and a resumed run must take the
  // same steps as an uninterrupted one. max_digits10 digits make the decimal
  // text an exact copy of the doubles.
  void
  LoadStepper::save(std::ostream &out) const
  {
    out << std::setprecision(std::numeric_limits<double>::max_digits10) << t
        << ' ' << increment << ' ' << n_steps;
    // Path following needs the peak force (the sign guard) and whether
    // the last step went back (allow_limit()).
    if (path_following())
      out << ' ' << F << ' ' << went_back << ' ' << F_peak;
  }



  void
  LoadStepper::load(std::istream &in)
  {
    in >> t >> increment >> n_steps;
    if (path_following())
      in >> F >> went_back >> F_peak;
    AssertThrow(in, ExcMessage("Cannot read the load stepping state."));
    cut_backs = 0;
  }
} // namespace qsmpm
