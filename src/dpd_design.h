// ETD-DPD: command dpd/design, DPD parameters (s, gamma) from a target viscosity and Schmidt
// number (or particle diffusion time), stored in LAMMPS variables.
#ifndef ETD_DPD_DESIGN_H
#define ETD_DPD_DESIGN_H

#include "command.h"
#include "kinetic_theory.h"

#include <string>

namespace LAMMPS_NS {

class DPDDesign : public Command {
 public:
  DPDDesign(class LAMMPS *lmp) : Command(lmp) {}
  void command(int, char **) override;

 private:
  struct Request;
  Request parse(int narg, char **arg);
  void refuse(const Request &request, const etd::kinetic::Design &design);
  void store_and_report(const Request &request, const etd::kinetic::Design &design);
};

}    // namespace LAMMPS_NS

#endif
