#include "scenario/telemetry_row.h"

#include <sstream>

#include "config/units.h"

namespace bdfcar::scenario {

namespace {
// Where the whole numbers and the 4-digit column sit (see header()).
constexpr int kNewtonIterations = 49, kNewtonCorrection = 50, kSegment = 51, kFidelity = 52;
constexpr int kGear = TelemetryRowMaker::kBaseColumns + 1;
}  // namespace

const char* TelemetryRowMaker::header() {
  return "time_s,x_m,y_m,z_m,roll_rad,pitch_rad,yaw_rad,vx_mps,yawrate_radps,ay_mps2,dz_com_m,rack_m,"
         "Fz_FL_N,Fz_FR_N,Fz_RL_N,Fz_RR_N,steer_in,pinion_deg,rack_cmd_m,ay_horiz_mps2,vy_mps,Tdrive_Nm,"
         "steer_FL_deg,steer_FR_deg,alpha_FL_rad,alpha_FR_rad,alpha_RL_rad,alpha_RR_rad,"
         "Fy_FL_N,Fy_FR_N,Fy_RL_N,Fy_RR_N,kappa_RL,kappa_RR,"
         "ax_mps2,speed_mps,throttle_in,brake_in,kappa_FL,kappa_FR,Fx_FL_N,Fx_FR_N,Fx_RL_N,Fx_RR_N,"
         "spin_FL_radps,spin_FR_radps,spin_RL_radps,spin_RR_radps,rack_force_N,newton_iterations,newton_correction,"
         "segment,fidelity,sideslip_rad,rollrate_radps,pitchrate_radps,steer_RL_deg,steer_RR_deg,"
         "camber_FL_deg,camber_FR_deg,camber_RL_deg,camber_RR_deg,toe_FL_deg,toe_FR_deg,toe_RL_deg,toe_RR_deg,"
         "travel_FL_m,travel_FR_m,travel_RL_m,travel_RR_m,Fspring_FL_N,Fspring_FR_N,Fspring_RL_N,Fspring_RR_N,"
         "Fdamper_FL_N,Fdamper_FR_N,Fdamper_RL_N,Fdamper_RR_N,Fstop_FL_N,Fstop_FR_N,Fstop_RL_N,Fstop_RR_N,"
         "Mz_FL_Nm,Mz_FR_Nm,Mz_RL_Nm,Mz_RR_Nm,switch_jump_m";
}

const char* TelemetryRowMaker::powertrainHeader() {
  return "engine_rpm,gear,clutch,clutch_slip_rpm,engine_torque_Nm,clutch_torque_Nm,engine_throttle,handbrake_in";
}

const char* TelemetryRowMaker::lapHeader() { return "lap,lap_time_s,lap_distance_m"; }

std::string TelemetryRowMaker::header(const vehicle::Vehicle& v, bool laps) {
  std::string h = header();
  if (v.spec.powertrain) h += std::string(",") + powertrainHeader();
  if (laps) h += std::string(",") + lapHeader();
  return h;
}

TelemetryRowMaker::TelemetryRowMaker(const vehicle::Vehicle& v, bool laps)
    : v_(v),
      laps_(laps),
      columns_(kBaseColumns + (v.spec.powertrain ? kPowertrainColumns : 0) + (laps ? kLapColumns : 0)) {}

std::vector<std::string> TelemetryRowMaker::names() const {
  std::vector<std::string> out;
  std::istringstream in(header(v_, laps_));
  for (std::string name; std::getline(in, name, ',');) out.push_back(name);
  return out;
}

ColumnFormat TelemetryRowMaker::format(int column) {
  if (column == kNewtonCorrection) return ColumnFormat::Real4;
  if (column == kNewtonIterations || column == kSegment || column == kFidelity || column == kGear)
    return ColumnFormat::Integer;
  return ColumnFormat::Real10;
}

void TelemetryRowMaker::fill(const vehicle::VehicleSample& s, const TelemetryInputs& in, Values& out) {
  if (first_) {
    z0_ = s.com.z();
    rack0_ = s.rack;
    first_ = false;
  }
  // Tdrive_Nm: the torque on a driven wheel (the reference applies it to each rear wheel).
  double drive = 0;
  for (int w = 0; w < 4; ++w)
    if (v_.wheel(w).driven) drive = s.driveTorque[w];
  const auto& st = v_.spec.steering;
  const double pinionDeg = config::radToDeg(st.steeringWheelFull * in.steer);
  double* o = out.data();
  auto put = [&o](std::initializer_list<double> values) {
    for (double x : values) *o++ = x;
  };
  put({s.t, s.com.x(), s.com.y(), s.com.z(), s.roll, s.pitch, s.yaw, s.vx, s.yawRate, s.ay, s.com.z() - z0_,
       s.rack - rack0_, s.Fz[0], s.Fz[1], s.Fz[2], s.Fz[3], in.steer, pinionDeg, st.rackTravelFull * in.steer,
       s.ayHorizontal, s.vy, drive, config::radToDeg(s.steerAngle[0]), config::radToDeg(s.steerAngle[1]),
       s.alpha[0], s.alpha[1], s.alpha[2], s.alpha[3], s.Fy[0], s.Fy[1], s.Fy[2], s.Fy[3], s.kappa[2],
       s.kappa[3], s.ax, s.speed, in.throttle, in.brake, s.kappa[0], s.kappa[1], s.Fx[0], s.Fx[1], s.Fx[2],
       s.Fx[3], s.spinRate[0], s.spinRate[1], s.spinRate[2], s.spinRate[3], s.rackForce});
  // The integer columns, then the suspension and tyre channels (appended
  // later: the columns before them keep their places).
  put({double(in.newtonIterations), in.newtonCorrection, double(in.segment), double(in.fidelity)});
  put({s.sideslip, s.rollRate, s.pitchRate, config::radToDeg(s.steerAngle[2]), config::radToDeg(s.steerAngle[3])});
  for (int w = 0; w < 4; ++w) *o++ = config::radToDeg(s.camber[w]);
  for (int w = 0; w < 4; ++w) *o++ = config::radToDeg(s.toe[w]);
  for (int w = 0; w < 4; ++w) *o++ = s.travel[w];
  for (int w = 0; w < 4; ++w) *o++ = s.springForce[w];
  for (int w = 0; w < 4; ++w) *o++ = s.damperForce[w];
  for (int w = 0; w < 4; ++w) *o++ = s.stopForce[w];
  for (int w = 0; w < 4; ++w) *o++ = s.Mz[w];
  *o++ = in.switchJump;
  if (v_.spec.powertrain) {
    const PowertrainChannels& pt = in.powertrain;
    put({pt.engineRpm, double(pt.gear), pt.clutch, pt.clutchSlipRpm, pt.engineTorque, pt.clutchTorque, pt.throttle,
         pt.handbrake});
  }
  if (laps_) put({double(in.laps.lap), in.laps.lapTime, in.laps.distance});  // the lap: a whole number, printed as one
}

}  // namespace bdfcar::scenario
