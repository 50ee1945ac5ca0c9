// Work that may lag runs below work that may not.
//
// On a machine with few cores a software rasteriser (Mesa's llvmpipe) competes
// with everything else for the same cores. Headless, drawing the next frame is
// the latency and encoding (the PNG worker, ffmpeg) is a queue that may lag,
// bounded by PngQueue's maxPending and ffmpeg's pipe. Interactive, the
// driver's 10 ms tick may not lag and drawing may (a frame is drawn from the
// latest state whenever the last one is done). A higher nice value lets the
// scheduler serve the other first; the total CPU work is unchanged, and the
// reports print wall time per frame beside the draw time.
#pragma once

namespace bdfcar::render {

inline constexpr int kBackgroundNiceness = 10;  // added to a thread's nice value (capped at 19)

// Raises the calling thread's nice value by kBackgroundNiceness (Linux: per
// thread). Best effort: a failure leaves the priority as it was.
void lowerThisThreadsPriority();

// The same for llvmpipe's rasteriser threads (named "llvmpipe-N"), which the
// GL context's creation started and which inherited its thread's priority.
// Returns how many were found: 0 with a GPU driver.
int lowerSoftwareRasteriserPriority();

}  // namespace bdfcar::render
