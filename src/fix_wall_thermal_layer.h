// ETD-DPD: fix wall/thermal/layer, velocities of the particles in a thin layer next to a plane
// wall redrawn from the wall's Maxwellian (see doc/fix_wall_thermal_layer.rst).
#ifndef ETD_FIX_WALL_THERMAL_LAYER_H
#define ETD_FIX_WALL_THERMAL_LAYER_H

#include "fix.h"

#include <cstdint>
#include <vector>

namespace LAMMPS_NS {

class FixWallThermalLayer : public Fix {
 public:
  FixWallThermalLayer(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void end_of_step() override;
  double compute_vector(int) override;

  struct Face {
    int dim;               // 0, 1, 2
    bool lower;            // xlo/ylo/zlo: fluid above the plane
    double position;       // the wall plane (box units)
    double thickness;      // of the layer
    double kT;             // wall temperature (energy units)
    double velocity[3];    // wall velocity (in the plane)
  };

 private:
  std::uint64_t seed;
  std::vector<Face> faces;
  double redrawn_last;     // atoms redrawn in the last step, all ranks
  double energy_change;    // kinetic energy added by the redraws since definition, all ranks
};

}    // namespace LAMMPS_NS

#endif
