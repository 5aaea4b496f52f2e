// ETD-DPD: command dpd/design, DPD parameters (s, gamma) from a target viscosity and Schmidt
// number (or particle diffusion time), stored in LAMMPS variables.
#ifndef ETD_DPD_DESIGN_H
#define ETD_DPD_DESIGN_H

#include "command.h"

namespace LAMMPS_NS {

class DPDDesign : public Command {
 public:
  DPDDesign(class LAMMPS *lmp) : Command(lmp) {}
  void command(int, char **) override;
};

}    // namespace LAMMPS_NS

#endif
