#include "vehicle/ladder.h"

namespace bdfcar::vehicle {

const std::array<RungDescription, 3>& ladder() {
  static const std::array<RungDescription, 3> rungs = {{
      {Fidelity::Linkage, "linkage", "the vehicle file's bodies, joints and cut joints",
       "every link of the suspension and steering, its loops closed by the cut-joint equations",
       "nothing the vehicle file describes (joint compliance is not in the file)", "-", "everywhere",
       "the reference the other rungs are certified against", false},
      {Fidelity::Kinematic, "kinematic", "a quasi-static sweep of the linkage (kinematic_model.h)",
       "each corner's carrier pose and spring length over travel and rack travel (toe, camber, track, "
       "wheelbase, bump and roll steer, anti-dive and anti-squat through the carrier's path), heave, roll "
       "and pitch of the chassis",
       "the links' own motion (their mass goes to the carriers and the chassis)",
       "the chassis, rack, rack travels and wheel spins carry over; travels from the linkage's carriers",
       "everywhere the linkage is (its tables span the sweep's travel)",
       "the battery against the linkage at the scene's step (rung_certificate.h)", true},
      {Fidelity::Planar, "planar", "the kinematic rung at rest on level ground (planar_model.h)",
       "plane motion, roll and pitch of the sprung body about an axis identified from the kinematic rung's "
       "steady roll, load transfer through the corner springs and the roll centres, steering tables at the "
       "static travel, each wheel's toe and camber over its travel to first order (bump and roll steer, camber "
       "gain), wheel spins",
       "heave, anti-dive and anti-squat (it pitches about the roll axis), the unsprung masses' own load transfer, "
       "toe and camber beyond first order in travel, the roll centres' migration, any ground but the road plane",
       "down: the base takes the sprung body's heading and roll-axis point, heave and travels are dropped "
       "(a switch that would move the body is refused); up: travels from the corner springs' deflection",
       "the ground under every wheel within 5 mm and 0.5 deg of the road plane, no wheel in the air, no tyre "
       "above 80 % of its friction, and the same for the road ahead",
       "the battery against the linkage at the scene's step (rung_certificate.h)", true},
  }};
  return rungs;
}

const RungDescription& describeRung(Fidelity f) { return ladder()[static_cast<int>(f)]; }

std::optional<Fidelity> rungByName(std::string_view name) {
  for (const RungDescription& r : ladder())
    if (name == r.name) return r.fidelity;
  return std::nullopt;
}

std::string rungNames() {
  std::string s;
  for (const RungDescription& r : ladder()) s += (s.empty() ? "" : ", ") + std::string(r.name);
  return s;
}

const char* fidelityName(Fidelity f) { return describeRung(f).name; }

}  // namespace bdfcar::vehicle
