// How many pixels the world is drawn with in a window that must keep its frame
// rate: a GPU short of fill rate (a large or high-density screen) draws the 3D
// view at 0.7 of the width and height for about half the pixel work, and its
// stretch over the window costs next to nothing; a GPU that meets the budget
// stays at full size. Not used on software GL, where the stretch costs what
// the smaller world saves (render/window.cpp). No GL here: the choice from
// frame times only.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace bdfcar::render {

// The world's scales, largest first (of the window's width and height).
inline constexpr std::array<double, 5> kResolutionSteps{1.0, 0.85, 0.7, 0.6, 0.5};

// Chooses the scale from the draw times of the last frames: a step down when
// their median misses the budget, a step up when the step up would meet it
// with a margin, its cost predicted as if all of it were per pixel (an
// overestimate: culling, geometry and the swap do not grow with the pixels),
// so that it does not swing between two steps.
class ResolutionGovernor {
 public:
  // budget: the frame time to keep under (s); window: frames per decision.
  explicit ResolutionGovernor(double budget = 1.0 / 30.0, int window = 15);
  // One frame's draw time (s), drawn at scale(); returns the scale for the next frame.
  double frame(double seconds);
  double scale() const { return kResolutionSteps[step_]; }

  // Of the budget, what a median may take: below 1 so that a p50 frame rate
  // stays above 1/budget with the frames' spread.
  static constexpr double kDownAt = 0.9;
  // Of kDownAt's time, what the step up's predicted median may take.
  static constexpr double kUpMargin = 0.8;

 private:
  double budget_;
  int window_;
  std::size_t step_ = 0;
  std::vector<double> recent_;
};

}  // namespace bdfcar::render
