// Encoders (PNG worker, ffmpeg) run below the renderer's priority.
//
// On a machine with few cores a software rasteriser (llvmpipe) and an encoder
// compete for the same cores: the frame being drawn waits while the previous
// one is compressed. Drawing is the latency that matters (the next frame needs
// it); encoding is a queue that may lag, bounded by PngQueue's maxPending and
// ffmpeg's pipe. A higher nice value lets the scheduler give the renderer the
// cores first. Total throughput is unchanged: the whole run still takes the
// CPU both need (reported as the wall time per frame).
#pragma once

namespace bdfcar::render {

inline constexpr int kEncoderNiceness = 10;  // added to the thread's nice value (capped at 19)

// Raises the calling thread's nice value by kEncoderNiceness (Linux: per
// thread). Best effort: a failure leaves the priority as it was.
void lowerThisThreadsPriority();

}  // namespace bdfcar::render
