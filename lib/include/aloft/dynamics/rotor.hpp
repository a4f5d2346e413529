// A rotor spinning inside the body whose speed is measured (a reaction wheel, a fan, a
// motor; SPEC §2 `rotor`). Its angular momentum relative to the body is
//   h = inertia_kg_m2 · speed · axis,
// and it is part of the body's model: I·dω/dt + ω × (I·ω + h) = −dh/dt, with I the whole
// assembly's tensor, rotor included. Its torque on the body is known, so it is never a
// landing; and since h is known in kg·m²/s, a flight with the rotor's speed fixes the
// tensor's absolute scale, which a torque-free flight cannot.
#pragma once

#include "aloft/dynamics/rotation.hpp"
#include "aloft/settings.hpp"

namespace aloft {

template <typename Scalar>
struct Rotor {
  Vec3<Scalar> axis = Vec3<Scalar>::UnitZ();  // spin axis, body axes, unit length
  Scalar inertia_kg_m2 = Scalar(0);           // moment about the spin axis; 0: no rotor

  bool present() const { return inertia_kg_m2 > Scalar(0); }
  // h at a speed relative to the body (rad/s; positive turns right-handed about axis).
  Vec3<Scalar> momentum(Scalar speed_rad_s) const { return (inertia_kg_m2 * speed_rad_s) * axis; }

  // The one list of these settings (aloft/settings.hpp).
  template <typename Self, typename Visitor>
  static void visit(Self& s, Visitor&& v) {
    v(s.axis, [] {
      return SettingInfo{"rotor.axis", "",
                         "the rotor's spin axis, body axes, unit length: a property of the body"};
    });
    v(s.inertia_kg_m2, [] {
      return SettingInfo{"rotor.inertia_kg_m2", "kg·m²",
                         "the rotor's moment about its spin axis; 0: no rotor. A property of the body "
                         "(SPEC §2 rotor), not tuned"};
    });
  }
};

}  // namespace aloft
