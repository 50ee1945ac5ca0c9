#include "scenario/telemetry.h"

#include <charconv>
#include <chrono>
#include <stdexcept>

#include "config/units.h"

namespace bdfcar::scenario {

const char* TelemetryWriter::header() {
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

const char* TelemetryWriter::powertrainHeader() {
  return "engine_rpm,gear,clutch,clutch_slip_rpm,engine_torque_Nm,clutch_torque_Nm,engine_throttle,handbrake_in";
}

std::string TelemetryWriter::header(const vehicle::Vehicle& v) {
  return v.spec.powertrain ? std::string(header()) + "," + powertrainHeader() : std::string(header());
}

TelemetryWriter::TelemetryWriter(const std::string& path, const vehicle::Vehicle& v)
    : file_(path), v_(v), queue_(kQueueRows) {
  file_.append(header(v) + "\n");
  thread_ = std::thread([this] { writerLoop(); });
}

TelemetryWriter::~TelemetryWriter() {
  try {
    close();
  } catch (const OutputError&) {
    // Reported by an explicit close(); a destructor must not throw.
  }
}

void TelemetryWriter::write(const vehicle::VehicleSample& s, const TelemetryInputs& in) {
  std::unique_lock lock(mutex_);
  rethrowWriterError();
  if (closed_) throw OutputError(file_.path() + ": written after it was closed");
  // Full: wait for the writer (a disk slower than the simulation), never drop.
  while (size_ == kQueueRows && !error_) {
    wake_.notify_one();
    written_.wait(lock);
  }
  rethrowWriterError();
  Row& r = queue_[(head_ + size_) % kQueueRows];
  r.sample = s;
  r.inputs = in;
  ++size_;
  // The writer sleeps between batches (writerLoop): wake it every kBatchRows
  // rows, so that a row costs no system call and a run faster than real time
  // is formatted alongside, not after.
  if (size_ % kBatchRows == 0) wake_.notify_one();
}

void TelemetryWriter::writerLoop() {
  std::unique_lock lock(mutex_);
  for (;;) {
    if (size_ == 0) {
      written_.notify_all();
      if (stop_) return;
      wake_.wait_for(lock, std::chrono::milliseconds(20));
      continue;
    }
    const Row& r = queue_[head_];
    busy_ = true;
    lock.unlock();
    try {
      formatRow(r);
    } catch (...) {
      lock.lock();
      busy_ = false;
      error_ = std::current_exception();
      size_ = 0;  // the rows after a failed write are lost with it; the caller is told
      written_.notify_all();
      return;
    }
    lock.lock();
    busy_ = false;
    head_ = (head_ + 1) % kQueueRows;
    --size_;
    if (size_ == kQueueRows - 1) written_.notify_all();  // a waiting write() may go on
  }
}

void TelemetryWriter::waitUntilWritten(std::unique_lock<std::mutex>& lock) {
  while ((size_ > 0 || busy_) && !error_) {
    wake_.notify_one();
    written_.wait(lock);
  }
}

// Once the writer thread failed, every later call says so (it has stopped).
void TelemetryWriter::rethrowWriterError() {
  if (error_) std::rethrow_exception(error_);
}

void TelemetryWriter::flush() {
  std::unique_lock lock(mutex_);
  waitUntilWritten(lock);
  rethrowWriterError();
  file_.flush();  // the writer thread is idle while the lock is held
}

void TelemetryWriter::close() {
  {
    std::unique_lock lock(mutex_);
    if (closed_) return;
    waitUntilWritten(lock);
    closed_ = stop_ = true;
    wake_.notify_one();
  }
  thread_.join();
  rethrowWriterError();  // the writer thread has ended: no lock needed
  file_.close();
}

void TelemetryWriter::formatRow(const Row& r) {
  const vehicle::VehicleSample& s = r.sample;
  const TelemetryInputs& in = r.inputs;
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
  // std::to_chars with a precision prints exactly what printf's %.10g does
  // (the C++ standard defines it so), at a fraction of the cost: a 53-column
  // row through snprintf cost as much as the physics step.
  const double values[] = {
      s.t, s.com.x(), s.com.y(), s.com.z(), s.roll, s.pitch, s.yaw, s.vx, s.yawRate, s.ay, s.com.z() - z0_,
      s.rack - rack0_, s.Fz[0], s.Fz[1], s.Fz[2], s.Fz[3], in.steer, pinionDeg, st.rackTravelFull * in.steer,
      s.ayHorizontal, s.vy, drive, config::radToDeg(s.steerAngle[0]), config::radToDeg(s.steerAngle[1]),
      s.alpha[0], s.alpha[1], s.alpha[2], s.alpha[3], s.Fy[0], s.Fy[1], s.Fy[2], s.Fy[3], s.kappa[2],
      s.kappa[3], s.ax, s.speed, in.throttle, in.brake, s.kappa[0], s.kappa[1], s.Fx[0], s.Fx[1], s.Fx[2],
      s.Fx[3], s.spinRate[0], s.spinRate[1], s.spinRate[2], s.spinRate[3], s.rackForce};
  // The suspension and tyre channels, after the integer columns (appended
  // later: the columns before them keep their places).
  double corners[7 * 4 + 5 + 1] = {s.sideslip, s.rollRate, s.pitchRate, config::radToDeg(s.steerAngle[2]),
                               config::radToDeg(s.steerAngle[3])};
  for (int w = 0; w < 4; ++w) {
    double* c = corners + 5 + w;
    c[0] = config::radToDeg(s.camber[w]);
    c[4] = config::radToDeg(s.toe[w]);
    c[8] = s.travel[w];
    c[12] = s.springForce[w];
    c[16] = s.damperForce[w];
    c[20] = s.stopForce[w];
    c[24] = s.Mz[w];
  }
  corners[7 * 4 + 5] = in.switchJump;
  char row[4096];
  char* p = row;
  char* const end = row + sizeof row;
  auto put = [&](std::to_chars_result r, char sep) {
    if (r.ec != std::errc() || r.ptr == end) throw OutputError(file_.path() + ": a telemetry row too long");
    p = r.ptr;
    *p++ = sep;
  };
  for (double v : values) put(std::to_chars(p, end, v, std::chars_format::general, 10), ',');
  put(std::to_chars(p, end, in.newtonIterations), ',');
  put(std::to_chars(p, end, in.newtonCorrection, std::chars_format::general, 4), ',');
  put(std::to_chars(p, end, in.segment), ',');
  put(std::to_chars(p, end, in.fidelity), ',');
  for (double v : corners) put(std::to_chars(p, end, v, std::chars_format::general, 10), ',');
  if (v_.spec.powertrain) {
    const PowertrainChannels& pt = in.powertrain;
    put(std::to_chars(p, end, pt.engineRpm, std::chars_format::general, 10), ',');
    put(std::to_chars(p, end, pt.gear), ',');
    for (double v : {pt.clutch, pt.clutchSlipRpm, pt.engineTorque, pt.clutchTorque, pt.throttle, pt.handbrake})
      put(std::to_chars(p, end, v, std::chars_format::general, 10), ',');
  }
  p[-1] = '\n';
  file_.append(row, static_cast<std::size_t>(p - row));
}

}  // namespace bdfcar::scenario
