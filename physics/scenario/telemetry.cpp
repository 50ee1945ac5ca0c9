#include "scenario/telemetry.h"

#include <charconv>
#include <chrono>
#include <stdexcept>


namespace bdfcar::scenario {

TelemetryWriter::TelemetryWriter(const std::string& path, const vehicle::Vehicle& v, bool laps)
    : file_(path), maker_(v, laps), queue_(kQueueRows) {
  file_.append(header(v, laps) + "\n");
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
  TelemetryRowMaker::Values values;
  maker_.fill(r.sample, r.inputs, values);
  // std::to_chars with a precision prints exactly what printf's %.10g does
  // (the C++ standard defines it so), at a fraction of the cost: a 53-column
  // row through snprintf cost as much as the physics step.
  char row[4096];
  char* p = row;
  char* const end = row + sizeof row;
  auto put = [&](std::to_chars_result r) {
    if (r.ec != std::errc() || r.ptr == end) throw OutputError(file_.path() + ": a telemetry row too long");
    p = r.ptr;
    *p++ = ',';
  };
  for (int i = 0; i < maker_.columns(); ++i) {
    const double v = values[i];
    switch (TelemetryRowMaker::format(i)) {
      case ColumnFormat::Real10: put(std::to_chars(p, end, v, std::chars_format::general, 10)); break;
      case ColumnFormat::Real4: put(std::to_chars(p, end, v, std::chars_format::general, 4)); break;
      case ColumnFormat::Integer: put(std::to_chars(p, end, static_cast<long>(v))); break;
    }
  }
  p[-1] = '\n';
  file_.append(row, static_cast<std::size_t>(p - row));
}

}  // namespace bdfcar::scenario
