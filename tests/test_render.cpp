// Renderer tests with a synthetic (kinematic, no physics) lane change. Built
// twice: test_render links the headless OSMesa backend; test_render_window
// (BDFCAR_TEST_WINDOW) links the SDL2 window backend and runs it on SDL's
// "offscreen" video driver. DISPLAY is unset: no display server is used.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>

#include <unistd.h>

#include "render/camera_rig.h"
#include "render/frame.h"
#include "render/gl_check.h"
#include "render/png_queue.h"
#include "render/obj_mesh.h"
#include "render/png_writer.h"
#include "render/scene.h"
#include "render/surface_sampler.h"
#include "render/synthetic_drive.h"
#include "render/video_pipe.h"
#ifdef BDFCAR_TEST_WINDOW
#include "render/window.h"
#else
#include "render/headless.h"
#endif

namespace bdfcar::render {
namespace {

namespace fs = std::filesystem;

SyntheticDrive laneChange() { return SyntheticDrive{scenario::makeIso3888Course(1.9, 0.0, -1.75)}; }

// Flat ground, two-lane road, the ISO 3888-1 course, the sedan body (pure red paint).
SceneConfig testScene(bool hud = true) {
  SceneConfig cfg;
  cfg.terrain.road.present = true;
  cfg.terrain.road.startX = -60;
  cfg.terrain.road.endX = 300;
  cfg.course = laneChange().course;
  cfg.geometry.bodyMesh = "assets/models/sedan_body.obj";
  cfg.geometry.bodyColour = Eigen::Vector3d(0.85, 0.05, 0.05);
  cfg.hud = hud;
  return cfg;
}

// Renders the scene's state through whichever backend this executable links.
class Renderer {
 public:
  Renderer(Scene& scene, int w, int h) {
    unsetenv("DISPLAY");
#ifdef BDFCAR_TEST_WINDOW
    setenv("SDL_VIDEODRIVER", "offscreen", 1);
    WindowOptions o;
    o.width = w;
    o.height = h;
    o.vsync = false;
    o.multisample = 0;
    window_ = std::make_unique<Window>(scene, o);
#else
    headless_ = std::make_unique<HeadlessRenderer>(scene, w, h);
#endif
  }
  Frame render() {
#ifdef BDFCAR_TEST_WINDOW
    Frame f;
    window_->present(&f);
    return f;
#else
    return headless_->render();
#endif
  }
#ifndef BDFCAR_TEST_WINDOW
  DrawLoad lastLoad() const { return headless_->lastLoad(); }
#endif

 private:
#ifdef BDFCAR_TEST_WINDOW
  std::unique_ptr<Window> window_;
#else
  std::unique_ptr<HeadlessRenderer> headless_;
#endif
};

// Pixels of the body paint: strongly red (lit or shaded).
bool isPaint(const std::uint8_t* p) { return p[0] > 90 && p[0] > 3 * p[1] && p[0] > 3 * p[2]; }

// Count of pixels in [x0, x1) x [y0, y1) (fractions of the frame) satisfying pred.
template <typename Pred>
int countPixels(const Frame& f, double x0, double x1, double y0, double y1, Pred pred) {
  int n = 0;
  for (int y = int(y0 * f.height); y < int(y1 * f.height); ++y)
    for (int x = int(x0 * f.width); x < int(x1 * f.width); ++x) n += pred(f.pixel(x, y)) ? 1 : 0;
  return n;
}

// Renders the synthetic lane change at time t.
Frame frameAt(Scene& scene, Renderer& r, double t) {
  const SyntheticFrame s = syntheticLaneChange(laneChange(), t);
  scene.update(s.view, s.hud);
  return r.render();
}

TEST(Render, LaneChangeFramesHaveRequestedSizeAndShowTheCarInTheChaseView) {
  Scene scene(testScene());
  ASSERT_TRUE(scene.warnings().empty()) << scene.warnings().front();
  Renderer r(scene, 320, 180);
  for (double t : {0.5, 2.0, 3.5, 5.0}) {  // straight, entering, in the side lane, leaving
    const Frame f = frameAt(scene, r, t);
    ASSERT_EQ(f.width, 320);
    ASSERT_EQ(f.height, 180);
    ASSERT_EQ(f.rgba.size(), 320u * 180u * 4u);
    EXPECT_FALSE(isAllBlack(f));
    // The chase camera keeps the car in the middle of the lower picture...
    const int centre = countPixels(f, 0.3, 0.7, 0.35, 0.95, isPaint);
    EXPECT_GT(centre, 0.08 * (0.4 * 320) * (0.6 * 180)) << "t = " << t;
    // ... and nowhere near the picture's left and right edges.
    EXPECT_LT(countPixels(f, 0.0, 0.15, 0.3, 1.0, isPaint) + countPixels(f, 0.85, 1.0, 0.3, 1.0, isPaint), 20);
  }
}

TEST(Render, SuccessiveFramesDifferAsTheCarMoves) {
  Scene scene(testScene());
  scene.setCamera(CameraMode::TopDown);  // world-fixed orientation: the road scrolls under the car
  Renderer r(scene, 320, 180);
  const Frame a = frameAt(scene, r, 2.0), b = frameAt(scene, r, 2.1);
  int changed = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4)
    changed += (std::abs(a.rgba[i] - b.rgba[i]) + std::abs(a.rgba[i + 1] - b.rgba[i + 1]) > 30) ? 1 : 0;
  EXPECT_GT(changed, 500);
}

TEST(Render, HudTextIsDrawn) {
  // Top left, above the horizon: with the HUD a dark panel holding bright text
  // strokes; without it only sky, which is never that dark.
  auto lum = [](const std::uint8_t* p) { return (p[0] + p[1] + p[2]) / 3; };
  int dark[2] = {0, 0}, bright[2] = {0, 0};
  for (int hud : {1, 0}) {
    Scene scene(testScene(hud == 1));
    Renderer r(scene, 320, 180);
    const Frame f = frameAt(scene, r, 1.0);
    dark[hud] = countPixels(f, 0.04, 0.3, 0.04, 0.28, [&](const std::uint8_t* p) { return lum(p) < 110; });
    bright[hud] = countPixels(f, 0.04, 0.3, 0.04, 0.28, [&](const std::uint8_t* p) { return lum(p) > 170; });
  }
  const int area = int(0.26 * 320) * int(0.24 * 180);
  EXPECT_GT(dark[1], area / 3);   // the panel
  EXPECT_GT(bright[1], 100);      // text on it
  EXPECT_LT(bright[1], area / 2);
  EXPECT_EQ(dark[0], 0);          // sky only
}

TEST(Render, EveryCameraModeRendersItsOwnView) {
  Scene scene(testScene());
  Renderer r(scene, 320, 180);
  std::vector<Frame> frames;
  for (CameraMode m : {CameraMode::Chase, CameraMode::Hood, CameraMode::Orbit, CameraMode::TopDown}) {
    scene.setCamera(m);
    frames.push_back(frameAt(scene, r, 2.5));
    EXPECT_FALSE(isAllBlack(frames.back())) << cameraName(m);
  }
  for (std::size_t i = 0; i < frames.size(); ++i)
    for (std::size_t j = i + 1; j < frames.size(); ++j) EXPECT_NE(frames[i].rgba, frames[j].rgba) << i << " vs " << j;
  EXPECT_EQ(scene.nextCamera(), CameraMode::Chase);
}

// Pixels of a 480 x 270 frame that `match`, with the body solid, hidden and translucent.
template <typename Match>
std::array<int, 3> pixelsPerBodyDisplay(Scene& scene, Match match) {
  Renderer r(scene, 480, 270);
  std::array<int, 3> n{};
  int i = 0;
  for (BodyDisplay d : {BodyDisplay::Solid, BodyDisplay::Hidden, BodyDisplay::Translucent}) {
    scene.setBodyDisplay(d);
    n[i++] = countPixels(frameAt(scene, r, 1.0), 0, 1, 0, 1, match);
  }
  return n;
}

TEST(Render, HiddenBodyShowsTheSuspensionStruts) {
  // Strut yellow (also seen through the 30 % body) appears only once the body stops hiding the links.
  auto strut = [](const std::uint8_t* p) { return p[0] > 150 && p[1] > 110 && p[2] < 90; };
  Scene scene(testScene(false));
  scene.setCamera(CameraMode::Orbit);
  scene.orbitBy(0.0, 0.0, 0.6);
  const auto [solid, hidden, translucent] = pixelsPerBodyDisplay(scene, strut);
  EXPECT_GT(hidden, solid + 30);
  EXPECT_GT(translucent, solid + 15);
}

// With the body hidden or see-through, the chassis is drawn as a frame of
// violet lines (unlit: 204, 153, 255) so that its roll and pitch still read;
// with the solid body, none of it shows.
TEST(Render, SuspensionViewsDrawTheChassisFrame) {
  auto violet = [](const std::uint8_t* p) {
    return std::abs(p[0] - 204) < 12 && std::abs(p[1] - 153) < 12 && std::abs(p[2] - 255) < 12;
  };
  Scene scene(testScene(false));
  scene.setCamera(CameraMode::Orbit);
  const auto [solid, hidden, translucent] = pixelsPerBodyDisplay(scene, violet);
  EXPECT_EQ(solid, 0);
  EXPECT_GT(hidden, 200);
  EXPECT_GT(translucent, 100);
}

// Solid body, camera above the bonnet looking down at it from the front
// left: the front struts' top mounts (docs/reference-vehicle.md) sit under the
// bonnet, so none of their yellow shows; with the body hidden they do. (With
// the bonnet 5 cm lower, as it was, their tops showed through it.)
TEST(Render, TheSolidBonnetCoversTheStrutTops) {
  auto strut = [](const std::uint8_t* p) { return p[0] > 150 && p[1] > 110 && p[2] < 90; };
  Scene scene(testScene(false));
  scene.setCamera(CameraMode::Orbit);
  const OrbitState o;
  scene.orbitBy(0.6 - o.yaw, 0.8 - o.pitch, 5.0 / o.distance);  // 0.6 rad left of the nose, 0.8 rad up, 5 m
  const auto [solid, hidden, translucent] = pixelsPerBodyDisplay(scene, strut);
  EXPECT_EQ(solid, 0);
  EXPECT_GT(hidden, 100);
  EXPECT_GT(translucent, 50);
}

// Reverse lights: unlit pure white (nothing else the chase camera sees behind
// the car is that white), lit in reverse gear only, and only on a car with a
// gearbox (a car without one reports gear 0).
TEST(Render, ReverseLightsLightInReverseGear) {
  auto white = [](const std::uint8_t* p) { return p[0] > 250 && p[1] > 250 && p[2] > 250; };
  Scene scene(testScene(false));
  Renderer r(scene, 960, 540);
  auto whitePixels = [&](bool powertrain, int gear) {
    SyntheticFrame s = syntheticLaneChange(laneChange(), 1.0);
    s.hud.powertrain = powertrain;
    s.hud.gear = gear;
    scene.update(s.view, s.hud);
    return countPixels(r.render(), 0.3, 0.7, 0.35, 0.95, white);
  };
  whitePixels(true, 1);  // the chase camera's first frame swings it from the start pose: settle it
  const int first = whitePixels(true, 1), reverse = whitePixels(true, -1), neutral = whitePixels(true, 0);
  const int noGearbox = whitePixels(false, -1), firstAgain = whitePixels(true, 1);
  EXPECT_GT(reverse, first + 40);
  EXPECT_EQ(neutral, first);
  EXPECT_EQ(noGearbox, first);
  EXPECT_EQ(firstAgain, first);  // and out again
}

// The HUD's g-g diagram: a dot of pure yellow (255, 214, 26), in the bottom
// left, at the acceleration seen from above with the car pointing up, its
// 1 g ring a tenth of the frame's height in radius: 0.5 g of braking
// (a_x < 0) moves it down by 0.05 of the height, 0.5 g to the left (a left
// turn, a_y > 0, docs/TELEMETRY.md) left by as much; it stops at 1.2 g.
TEST(Render, GgDotSitsAtTheAccelerationSeenFromAbove) {
  auto yellow = [](const std::uint8_t* p) {
    return std::abs(p[0] - 255) < 12 && std::abs(p[1] - 214) < 12 && std::abs(p[2] - 26) < 12;
  };
  constexpr double g = 9.80665;
  Scene scene(testScene());
  Renderer r(scene, 960, 540);
  // Centre of the dot's pixels in the bottom left quarter (x right, y down, pixels).
  auto dot = [&](double ax, double ay) {
    SyntheticFrame s = syntheticLaneChange(laneChange(), 1.0);  // one time: no trail
    s.hud.longitudinalAcceleration = ax;
    s.hud.lateralAcceleration = ay;
    scene.update(s.view, s.hud);
    const Frame f = r.render();
    double sx = 0, sy = 0;
    int n = 0;
    for (int y = f.height / 2; y < f.height; ++y)
      for (int x = 0; x < f.width / 2; ++x)
        if (yellow(f.pixel(x, y))) {
          sx += x + 0.5;
          sy += y + 0.5;
          ++n;
        }
    EXPECT_GT(n, 20) << ax << ", " << ay;
    return Eigen::Vector2d(sx / std::max(n, 1), sy / std::max(n, 1));
  };
  const double ring = 0.1 * 540;  // pixels per g
  const Eigen::Vector2d centre = dot(0, 0);
  EXPECT_LT(centre.x(), 0.2 * 960);
  EXPECT_GT(centre.y(), 0.6 * 540);
  const struct {
    double ax, ay;        // m/s^2
    Eigen::Vector2d move;  // pixels, x right, y down
  } cases[] = {{-0.5 * g, 0.0, {0.0, 0.5 * ring}},                // braking: down
               {0.0, 0.5 * g, {-0.5 * ring, 0.0}},                // turning left: left
               {0.3 * g, -0.4 * g, {0.4 * ring, -0.3 * ring}},    // accelerating out of a right turn
               {-2.0 * g, 0.0, {0.0, 1.2 * ring}}};               // beyond the panel: held at 1.2 g
  for (const auto& c : cases) {
    const Eigen::Vector2d moved = dot(c.ax, c.ay) - centre;
    EXPECT_NEAR(moved.x(), c.move.x(), 1.0) << c.ax << ", " << c.ay;
    EXPECT_NEAR(moved.y(), c.move.y(), 1.0) << c.ax << ", " << c.ay;
  }
}

TEST(Render, FullHdFrameAt1280x720) {
  Scene scene(testScene());
  Renderer r(scene, 1280, 720);
  const Frame f = frameAt(scene, r, 3.0);
  ASSERT_EQ(f.width, 1280);
  ASSERT_EQ(f.height, 720);
  EXPECT_GT(countPixels(f, 0.3, 0.7, 0.35, 0.95, isPaint), 20000);
}

TEST(Render, MissingBodyMeshFallsBackToABoxWithAWarning) {
  SceneConfig cfg = testScene();
  cfg.geometry.bodyMesh = "assets/models/no_such_body.obj";
  Scene scene(cfg);
  ASSERT_EQ(scene.warnings().size(), 1u);
  EXPECT_NE(scene.warnings()[0].find("no_such_body.obj"), std::string::npos);
  Renderer r(scene, 320, 180);
  EXPECT_GT(countPixels(frameAt(scene, r, 1.0), 0.3, 0.7, 0.35, 0.95, isPaint), 500);
}

#ifndef BDFCAR_TEST_WINDOW
// What a frame drew, counted: the same view with a body mesh of one
// material and with the fallback box differs by the mesh's triangles (a
// face of n corners is n - 2 of them) less the box's 24, in as many drawables.
TEST(Render, TheDrawLoadCountsTheTrianglesDrawn) {
  // A pyramid over a pentagon, 1.4 m high, in the chassis frame: 3 + 5 triangles.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("bdfcar_draw_load_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string mesh = (dir / "pyramid.obj").string();
  {
    std::ofstream obj(mesh);
    for (int k = 0; k < 5; ++k)
      obj << "v " << 2.0 * std::cos(2 * std::numbers::pi * k / 5) << " " << 0.8 * std::sin(2 * std::numbers::pi * k / 5) << " 0\n";
    obj << "v 0 0 1.4\nf 5 4 3 2 1\nf 1 2 6\nf 2 3 6\nf 3 4 6\nf 4 5 6\nf 5 1 6\n";
  }
  auto drawn = [](const std::string& body) {
    SceneConfig cfg = testScene();
    cfg.geometry.bodyMesh = body;
    Scene scene(cfg);
    Renderer r(scene, 320, 180);
    frameAt(scene, r, 1.0);
    return r.lastLoad();
  };
  const DrawLoad pyramid = drawn(mesh), box = drawn((dir / "no_such_body.obj").string());
  std::filesystem::remove_all(dir);
  EXPECT_GT(box.drawables, 0u);
  EXPECT_EQ(pyramid.drawables, box.drawables);
  EXPECT_EQ(long(pyramid.triangles) - long(box.triangles), 8 - 24);
}
#endif

#ifndef BDFCAR_TEST_WINDOW
// Past the haze's end everything is the fog's colour: a road whose markings
// run on 4 km draws as many pieces as one ending 200 m past the haze (the
// pieces beyond are culled, not drawn), and the same picture to a grey level.
TEST(Render, WhatLiesPastTheHazeIsCulled) {
  struct Drawn {
    Frame frame;
    DrawLoad load;
  };
  auto drawn = [](double roadEnd) {
    SceneConfig cfg = testScene(/*hud=*/false);
    cfg.terrain.road.endX = roadEnd;
    Scene scene(cfg);
    Renderer r(scene, 320, 180);
    Drawn d{frameAt(scene, r, 1.0), {}};
    d.load = r.lastLoad();
    return d;
  };
  const Drawn past = drawn(kHazeEnd + 200.0), far = drawn(4000.0);
  EXPECT_EQ(far.load.drawables, past.load.drawables);  // (the asphalt under the paint is one ribbon, drawn whole)
  int worst = 0;
  for (int y = 0; y < past.frame.height; ++y)
    for (int x = 0; x < past.frame.width; ++x)
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(past.frame.pixel(x, y)[c]) - int(far.frame.pixel(x, y)[c])));
  EXPECT_LE(worst, 1);
}
#endif

TEST(Render, StartUpCheckFailuresAreErrorsNotBlackPictures) {
  EXPECT_THROW(requireGlContext(nullptr, "test"), RenderError);
  try {
    requireGlContext(reinterpret_cast<const unsigned char*>(""), "test backend");
    FAIL() << "an empty GL_RENDERER must be rejected";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find("GL_RENDERER"), std::string::npos);
  }
  const Frame black = makeFrame(8, 8);
  EXPECT_TRUE(isAllBlack(black));
  EXPECT_THROW(requireNotBlack(black, "test"), RenderError);
  EXPECT_THROW(makeFrame(0, 10), RenderError);
}

#ifdef BDFCAR_TEST_WINDOW
// Multisampling left to the window (-1) is none on a software rasteriser, which
// pays for every sample (the proving ground: 72 ms a frame with 4, 26 without);
// asked for, it is what the context offers (4, or none where unsupported).
TEST(Render, WindowMultisamplesOnlyWhereItIsCheap) {
  setenv("SDL_VIDEODRIVER", "offscreen", 1);
  Scene scene(testScene());
  WindowOptions o;
  o.width = 64;
  o.height = 36;
  o.vsync = false;
  {
    Window automatic(scene, o);
    ASSERT_NE(automatic.glRenderer().find("llvmpipe"), std::string::npos) << automatic.glRenderer();
    EXPECT_EQ(automatic.samples(), 0);
  }
  o.multisample = 4;
  Window asked(scene, o);
  EXPECT_TRUE(asked.samples() == 4 || asked.samples() == 0) << asked.samples();
}

// The drive's reduced resolution (WindowOptions::renderScale): the world drawn
// at half the width and height and stretched is the full-resolution picture,
// blurred; the HUD over it is drawn at full resolution, as sharp as before.
TEST(Render, AWorldAtHalfResolutionIsTheSamePictureStretchedUnderASharpHud) {
  setenv("SDL_VIDEODRIVER", "offscreen", 1);
  Scene scene(testScene());
  const SyntheticFrame s = syntheticLaneChange(laneChange(), 2.0);
  scene.update(s.view, s.hud);
  WindowOptions o;
  o.width = 320;
  o.height = 180;
  o.vsync = false;
  o.multisample = 0;
  Frame full, half;
  {
    Window w(scene, o);
    w.present(&full);
    EXPECT_EQ(w.worldScale(), 1.0);
  }
  o.renderScale = 0.5;
  Window w(scene, o);
  w.present(&half);
  EXPECT_EQ(w.worldScale(), 0.5);
  ASSERT_EQ(half.width, 320);
  ASSERT_EQ(half.height, 180);
  // Mean difference of the two pictures over a region, per channel, of 4x4 blocks' means.
  auto blockDifference = [&](double x0, double x1, double y0, double y1, int block) {
    double sum = 0;
    int n = 0;
    for (int by = int(y0 * full.height); by + block <= int(y1 * full.height); by += block)
      for (int bx = int(x0 * full.width); bx + block <= int(x1 * full.width); bx += block)
        for (int c = 0; c < 3; ++c) {
          double a = 0, b = 0;
          for (int y = by; y < by + block; ++y)
            for (int x = bx; x < bx + block; ++x) {
              a += full.pixel(x, y)[c];
              b += half.pixel(x, y)[c];
            }
          sum += std::abs(a - b) / (block * block);
          ++n;
        }
    return sum / n;
  };
  // The world, the whole frame's lower part (road, cones, car), at 4x4 blocks:
  // the same picture to a few levels of 255, the edges included.
  EXPECT_LT(blockDifference(0, 1, 0.3, 1, 4), 6.0);
  EXPECT_LT(blockDifference(0.9, 1, 0.3, 1, 4), 8.0);  // no stale texels along the right edge
  // The car is where it was, as big.
  const int paintFull = countPixels(full, 0.3, 0.7, 0.35, 0.95, isPaint);
  const int paintHalf = countPixels(half, 0.3, 0.7, 0.35, 0.95, isPaint);
  EXPECT_NEAR(paintHalf, paintFull, 0.15 * paintFull);
  // The HUD's top-left panel, pixel for pixel: its text is not blurred (the
  // full frame's panel box-blurred 2x2 differs from it by 11.6).
  EXPECT_LT(blockDifference(0.04, 0.3, 0.04, 0.28, 1), 2.0);
}
#else
TEST(Render, GlCallsResolveToOsMesaInTheHeadlessExecutable) {
  // The link-order trap: if glvnd's libGL came first, gl* would resolve there and frames would be black.
  EXPECT_NE(glSymbolProvider("glGetString").find("OSMesa"), std::string::npos) << glSymbolProvider("glGetString");
  Scene scene(testScene());
  EXPECT_THROW(HeadlessRenderer(scene, 0, 0), RenderError);
  HeadlessRenderer r(scene, 64, 36);
  EXPECT_NE(r.glRenderer().find("llvmpipe"), std::string::npos) << r.glRenderer();
}
#endif

// A temporary path of this process's own: test_render and test_render_window
// run the same tests, side by side under `ctest -j`.
fs::path ownTemp(const std::string& stem, const std::string& extension = "") {
  return fs::temp_directory_path() / (stem + "_" + std::to_string(::getpid()) + extension);
}

TEST(RenderOutput, PngFilesAreWrittenDirectlyAndByTheWorkerThread) {
  const fs::path dir = ownTemp("bdfcar_test_render_png");
  fs::create_directories(dir);
  Frame f = makeFrame(16, 8);
  for (std::size_t i = 0; i < f.rgba.size(); ++i) f.rgba[i] = static_cast<std::uint8_t>(i * 7);
  writePng((dir / "direct.png").string(), f);
  {
    PngQueue queue(1, 2);
    for (int i = 0; i < 5; ++i) queue.push((dir / ("q" + std::to_string(i) + ".png")).string(), f);
    queue.flush();
    EXPECT_EQ(queue.written(), 5);
    queue.push((dir / "missing-folder" / "x.png").string(), f);
    EXPECT_THROW(queue.flush(), RenderError);
  }
  for (const char* name : {"direct.png", "q0.png", "q4.png"}) {
    std::ifstream in(dir / name, std::ios::binary);
    char sig[8] = {};
    in.read(sig, 8);
    EXPECT_EQ(std::string(sig + 1, 3), "PNG") << name;
  }
  fs::remove_all(dir);
}

TEST(RenderOutput, VideoThroughFfmpeg) {
  if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0) GTEST_SKIP() << "ffmpeg not installed";
  const fs::path file = ownTemp("bdfcar_test_render", ".mp4");
  {
    VideoPipe video(file.string(), 33, 17, VideoOptions{25.0});  // odd size: padded to even
    Frame f = makeFrame(33, 17);
    for (int i = 0; i < 10; ++i) {
      std::fill(f.rgba.begin(), f.rgba.end(), static_cast<std::uint8_t>(20 * i));
      video.write(f);
    }
    EXPECT_THROW(video.write(makeFrame(8, 8)), RenderError);
    video.close();
    EXPECT_EQ(video.frames(), 10);
  }
  EXPECT_GT(fs::file_size(file), 100u);
  fs::remove(file);
}

TEST(RenderGeometry, SurfaceSamplerInterpolatesTheTerrainTriangles) {
  terrain::TriangleMesh m;
  m.vertices = {{0, 0, 0}, {10, 0, 1}, {10, 10, 2}, {0, 10, 1}};  // plane z = 0.1 x + 0.1 y
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  const SurfaceSampler s(m, 4);
  EXPECT_NEAR(*s.height(2.0, 3.0), 0.5, 1e-9);
  EXPECT_NEAR(*s.height(9.0, 1.0), 1.0, 1e-9);
  EXPECT_FALSE(s.height(-1.0, 5.0).has_value());
  EXPECT_EQ(s.heightOr(20.0, 5.0, -3.0), -3.0);
}

TEST(RenderGeometry, ChaseCameraSitsBehindAndAboveTheCarWhateverItsHeading) {
  vehicle::BodyPose pose;
  pose.position = Eigen::Vector3d(5, 2, 0.5);
  pose.rotation = Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ());
  const CameraPose c = cameraPose(CameraMode::Chase, pose, OrbitState{});
  const Eigen::Vector3d forward(std::cos(1.0), std::sin(1.0), 0);
  EXPECT_LT((c.eye - pose.position).dot(forward), -5.0);
  EXPECT_GT(c.eye.z(), pose.position.z() + 1.0);
  EXPECT_GT((c.centre - c.eye).dot(forward), 0.0);
  EXPECT_NEAR(headingOf(pose), 1.0, 1e-12);
}


// The chase camera's heading follows the car's on a critically damped spring:
// after a step of the car's heading the lag is e0 (1 + w t) exp(-w t) (its
// motion over a frame is exact), and in a steady turn at yaw rate r it
// settles 2 r / w behind, less the half frame by which each frame's target
// leads (r dt / 2: a staircase through the ramp's frame values).
TEST(RenderGeometry, ChaseCameraHeadingLagsTheCarsOnACriticallyDampedSpring) {
  const double w = ChaseHeading::kOmega, dt = 1.0 / 60.0, step = 0.5;
  ChaseHeading h;
  h.update(0.0, 0.0);
  for (int i = 1; i <= 90; ++i) {
    const double t = i * dt;
    const double lag = step - h.update(step, t);
    if (i % 15 == 0) {
      EXPECT_NEAR(lag, step * (1 + w * t) * std::exp(-w * t), 1e-12) << "t = " << t;
    }
  }
  ChaseHeading turn;
  const double r = 20.0 * M_PI / 180.0;
  double car = 0;
  for (int i = 0; i <= 600; ++i) turn.update(car = r * i * dt, i * dt);
  EXPECT_NEAR(car - turn.heading(), 2 * r / w - r * dt / 2, 1e-3 * 2 * r / w);
  // Across the +-pi seam it goes the short way; a rewind (time going back) snaps it.
  ChaseHeading seam;
  seam.update(M_PI - 0.05, 0.0);
  seam.update(-M_PI + 0.05, dt);
  EXPECT_GT(std::remainder(seam.heading() - (M_PI - 0.05), 2 * M_PI), 0.0);  // turned through +pi, not back through 0
  EXPECT_EQ(seam.update(1.0, 0.0), 1.0);
}

// The car body's OBJ goes through config::LineReader's limits as the
// terrain's does (tests/cli/line_limits.sh runs those through the program):
// a line over 64 KiB is refused at its line, and a small file still reads
// (one square, two triangles).
TEST(ObjMesh, ReadUnderTheLineLimits) {
  const std::string good = ownTemp("bdfcar_square", ".obj").string(), bad = ownTemp("bdfcar_long_line", ".obj").string();
  std::ofstream(good) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  EXPECT_EQ(loadObj(good).triangles(), 2u);
  std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3" << std::string(70000, ' ') << "\n";
  try {
    (void)loadObj(bad);
    ADD_FAILURE() << "a 70,000-byte line was read";
  } catch (const RenderError& e) {
    EXPECT_NE(std::string(e.what()).find(bad + ":4: this line of the OBJ file is longer than 64 KiB"),
              std::string::npos)
        << e.what();
  }
  std::filesystem::remove(good);
  std::filesystem::remove(bad);
}

}  // namespace
}  // namespace bdfcar::render
