// ETD-DPD: command dpd/design. The physics is in kinetic_theory.h; this file parses the
// arguments, refuses impossible fluids with the bound that was violated, prints the design
// and stores it in equal-style variables for pair_coeff.
#include "dpd_design.h"

#include "comm.h"
#include "error.h"
#include "input.h"
#include "kinetic_theory.h"
#include "utils.h"
#include "variable.h"

#include <cmath>
#include <cstdlib>
#include <string>

using namespace LAMMPS_NS;
namespace kt = etd::kinetic;

namespace {

const char *usage = "dpd/design name eta V sc V|taup V density V mass V temp V cutoff V";

struct Keyword {
  const char *name;
  const char *meaning;
  double value;
  bool given;
};

}    // namespace

// What the user asked for, checked: the target viscosity, Schmidt number or particle diffusion
// time, and the fluid's state.
struct DPDDesign::Request {
  std::string name;
  double eta = 0.0, target = 0.0;    // target: Sc or tau_P
  bool by_schmidt = true;
  etd::kinetic::FluidState fluid;
  std::string state() const
  {
    return fmt::format("n = {}, m = {}, kBT = {}, cutoff = {}", fluid.number_density, fluid.mass,
                       fluid.temperature, fluid.cutoff);
  }
};

void DPDDesign::command(int narg, char **arg)
{
  const Request request = parse(narg, arg);
  const kt::Design design = request.by_schmidt
      ? kt::design_from_schmidt(request.fluid, request.eta, request.target)
      : kt::design_from_particle_diffusion_time(request.fluid, request.eta, request.target);
  if (!design.feasible) refuse(request, design);
  store_and_report(request, design);
}

DPDDesign::Request DPDDesign::parse(int narg, char **arg)
{
  if (narg < 1) error->all(FLERR, "Illegal dpd/design command: expected '{}'", usage);
  const std::string name = arg[0];
  if (!utils::is_id(name))
    error->all(FLERR,
               "dpd/design: name '{}' must contain only letters, digits and underscores "
               "(it prefixes the variables the command sets)",
               name);
  if (utils::is_double(name))
    error->all(FLERR,
               "dpd/design: the first argument is the name of the design, got the "
               "number '{}'; expected '{}'",
               name, usage);

  Keyword keys[] = {
      {"eta", "viscosity", 0.0, false},
      {"sc", "Schmidt number", 0.0, false},
      {"taup", "particle diffusion time", 0.0, false},
      {"density", "number density", 0.0, false},
      {"mass", "particle mass", 0.0, false},
      {"temp", "temperature kBT", 0.0, false},
      {"cutoff", "cutoff", 0.0, false},
  };
  enum { ETA, SC, TAUP, DENSITY, MASS, TEMP, CUTOFF, NKEYS };

  for (int iarg = 1; iarg < narg; iarg += 2) {
    const std::string word = arg[iarg];
    int k = 0;
    while (k < NKEYS && word != keys[k].name) ++k;
    if (k == NKEYS)
      error->all(FLERR, "dpd/design: unknown keyword '{}'; expected '{}'", word, usage);
    if (keys[k].given) error->all(FLERR, "dpd/design: keyword '{}' given twice", word);
    if (iarg + 1 >= narg) error->all(FLERR, "dpd/design: keyword '{}' needs a value", word);
    const std::string text = arg[iarg + 1];
    if (!utils::is_double(text))
      error->all(FLERR, "dpd/design: {} ({}) must be a number, got '{}'", word, keys[k].meaning,
                 text);
    const double value = std::strtod(text.c_str(), nullptr);
    if (!std::isfinite(value) || value <= 0.0)
      error->all(FLERR, "dpd/design: {} ({}) must be a finite number > 0, got {}", word,
                 keys[k].meaning, text);
    keys[k].value = value;
    keys[k].given = true;
  }

  if (keys[SC].given && keys[TAUP].given)
    error->all(FLERR, "dpd/design: give either sc or taup, not both (each fixes the diffusivity)");
  if (!keys[SC].given && !keys[TAUP].given)
    error->all(FLERR,
               "dpd/design: missing keyword sc or taup (Schmidt number or particle "
               "diffusion time); expected '{}'",
               usage);
  for (int k : {ETA, DENSITY, MASS, TEMP, CUTOFF})
    if (!keys[k].given)
      error->all(FLERR, "dpd/design: missing keyword {} ({}); expected '{}'", keys[k].name,
                 keys[k].meaning, usage);

  Request request;
  request.name = name;
  request.eta = keys[ETA].value;
  request.by_schmidt = keys[SC].given;
  request.target = request.by_schmidt ? keys[SC].value : keys[TAUP].value;
  request.fluid = {keys[DENSITY].value, keys[MASS].value, keys[TEMP].value, keys[CUTOFF].value};
  return request;
}

// an impossible fluid: say which bound it violates, in both directions
void DPDDesign::refuse(const Request &request, const kt::Design &design)
{
  const kt::FluidState &fluid = request.fluid;
  const double eta = request.eta;
  if (request.by_schmidt)
    error->all(FLERR,
               "dpd/design: no exponent s > 0 gives eta = {} with Sc = {} at {} "
               "(E = {:.6g}, needs E > 20): Sc must exceed {:.6g} at this eta, or eta must be "
               "below {:.6g} at this Sc",
               eta, request.target, request.state(), design.e, kt::min_schmidt_number(fluid, eta),
               kt::max_viscosity_for_schmidt(fluid, request.target));
  error->all(FLERR,
             "dpd/design: no exponent s > 0 gives eta = {} with tau_P = {} at {} "
             "(E = {:.6g}, needs E > 20): tau_P must exceed {:.6g} at this eta, or eta must "
             "be below {:.6g} at this tau_P",
             eta, request.target, request.state(), design.e,
             kt::min_particle_diffusion_time(fluid, eta),
             kt::max_viscosity_for_particle_diffusion_time(fluid, request.target));
}

// the design into equal-style variables NAME_s, NAME_gamma, ..., and its kinetic theory to the log
void DPDDesign::store_and_report(const Request &request, const kt::Design &design)
{
  const kt::FluidState &fluid = request.fluid;
  const std::string &name = request.name;
  const double eta = request.eta;
  const double s = design.s;
  const double gamma = design.gamma;
  const double sigma = std::sqrt(2.0 * gamma * fluid.temperature);
  const double eta_kinetic = kt::kinetic_viscosity(fluid, gamma, s);
  const double eta_total = kt::viscosity(fluid, gamma, s);
  const double diffusivity = kt::diffusivity(fluid, gamma, s);
  const double schmidt = kt::schmidt_number(fluid, gamma, s);
  const double tau_p = kt::particle_diffusion_time(fluid.temperature, eta, diffusivity);
  const double l0 = kt::correlation_length(fluid, gamma, s);

  const std::pair<const char *, double> outputs[] = {
      {"s", s},           {"gamma", gamma}, {"sigma", sigma}, {"eta", eta_total},
      {"D", diffusivity}, {"Sc", schmidt},  {"tauP", tau_p},  {"E", design.e},
  };
  std::string names;
  for (const auto &out : outputs) {
    const std::string var = name + "_" + out.first;
    input->variable->set(fmt::format("{} equal {:.17g}", var, out.second));
    names += " " + var;
  }

  if (comm->me == 0) {
    const std::string target = request.by_schmidt ? fmt::format("Sc = {}", request.target)
                                                  : fmt::format("tau_P = {}", request.target);
    utils::logmesg(lmp, "dpd/design {}: eta = {} and {} at {}\n", name, eta, target,
                   request.state());
    utils::logmesg(lmp, "  E = {:.8g}  ->  s = {:.8g}, gamma = {:.8g}, sigma = {:.8g}\n", design.e,
                   s, gamma, sigma);
    utils::logmesg(lmp,
                   "  kinetic theory of this fluid: eta = {:.6g} (dissipative {:.6g} + "
                   "kinetic {:.4g}), D = {:.6g}, Sc = {:.6g}, tau_P = {:.6g}, l0 = {:.4g}\n",
                   eta_total, eta_total - eta_kinetic, eta_kinetic, diffusivity, schmidt, tau_p,
                   l0);
    utils::logmesg(lmp, "  variables:{}\n", names);
  }
  // The design imposes the dissipative part of eta; say so when the kinetic part matters.
  if (eta_kinetic > 0.01 * eta)
    error->warning(FLERR,
                   "dpd/design {}: the kinetic part of the viscosity ({:.4g}) is {:.2g} % "
                   "of eta; the design imposes only the dissipative part",
                   name, eta_kinetic, 100.0 * eta_kinetic / eta);
  if (l0 >= fluid.cutoff)
    error->warning(FLERR,
                   "dpd/design {}: correlation length l0 = {:.4g} is not below the "
                   "cutoff {}: particle regime, where the kinetic-theory estimates are poor",
                   name, l0, fluid.cutoff);
}
