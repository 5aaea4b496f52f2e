// ETD-DPD: fix wall/cylinder/bounce, bounce-back reflection on a cylinder surface
// (see doc/fix_wall_cylinder_bounce.rst).
#ifndef ETD_FIX_WALL_CYLINDER_BOUNCE_H
#define ETD_FIX_WALL_CYLINDER_BOUNCE_H

#include "fix.h"

namespace LAMMPS_NS {

class FixWallCylinderBounce : public Fix {
 public:
  FixWallCylinderBounce(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void post_integrate() override;
  double compute_vector(int) override;

 private:
  int axis;            // 0, 1, 2 = x, y, z
  double centre[3];    // a point on the axis (axial component unused)
  double radius;
  bool fluid_inside;    // side in: the group lives inside the cylinder
  double dt;
  double bounces_local, projections_local;    // since the fix was defined, this rank
};

}    // namespace LAMMPS_NS

#endif
