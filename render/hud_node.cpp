#include "render/hud_node.h"

#include "scenario/lap_timer.h"

#include <osg/BlendFunc>
#include <osg/Geode>
#include <osgText/Font>
#include <osgText/Glyph>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace bdfcar::render {
namespace {

constexpr int kFigureColumns = 21, kFigureLines = 7;

// A bold monospaced TrueType font if one is installed, else OSG's built-in font.
osg::ref_ptr<osgText::Font> loadFont(bool& unicode) {
  for (const char* path : {"/usr/share/fonts/truetype/dejavu/DejaVuSansMono-Bold.ttf",
                           "/usr/share/fonts/truetype/liberation/LiberationMono-Bold.ttf",
                           "/usr/share/fonts/truetype/noto/NotoSansMono-Bold.ttf"}) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) continue;
    if (osg::ref_ptr<osgText::Font> f = osgText::readRefFontFile(path)) {
      unicode = true;
      return f;
    }
  }
  unicode = false;
  return osgText::Font::getDefaultFont();
}

// osgText gives its glyph textures trilinear filtering with 16x anisotropy.
// Software GL (llvmpipe) pays for every one of those samples: a sixth of the
// whole frame at 1280x720 went to the HUD's few hundred glyphs. The HUD draws
// glyphs near their rasterised size (layout() matches the font resolution to
// the character size), so one bilinear sample per pixel looks the same.
// Textures are added as glyphs are first used: called after every setText.
void useBilinearGlyphs(osgText::Font& font) {
  for (const osg::ref_ptr<osgText::GlyphTexture>& texture : font.getGlyphTextureList()) {
    // Only on change: each setter dirties the texture's parameters.
    if (texture->getFilter(osg::Texture::MIN_FILTER) != osg::Texture::LINEAR)
      texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR);
    if (texture->getMaxAnisotropy() != 1.0f) texture->setMaxAnisotropy(1.0f);
  }
}

// printf into a std::string.
template <typename... Args>
std::string format(const char* fmt, Args... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

// Axis-aligned quad from (x0, y0) to (x1, y1) appended to a vertex array.
void addRect(osg::Vec3Array& v, float x0, float y0, float x1, float y1) {
  v.push_back({x0, y0, 0});
  v.push_back({x1, y0, 0});
  v.push_back({x1, y1, 0});
  v.push_back({x0, y1, 0});
}

}  // namespace

HudNode::HudNode() : camera_(new osg::Camera) {
  camera_->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
  camera_->setRenderOrder(osg::Camera::POST_RENDER);
  camera_->setClearMask(0);  // drawn without depth test: no need to clear it
  camera_->setAllowEventFocus(false);
  camera_->setViewMatrix(osg::Matrix::identity());
  osg::StateSet* ss = camera_->getOrCreateStateSet();
  ss->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
  ss->setMode(GL_FOG, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
  ss->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
  ss->setMode(GL_BLEND, osg::StateAttribute::ON);
  ss->setAttributeAndModes(new osg::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA));

  font_ = loadFont(unicode_);
  panels_ = new osg::Geometry;
  panels_->setUseDisplayList(false);
  panels_->setDataVariance(osg::Object::DYNAMIC);
  osg::ref_ptr<osg::Vec4Array> shade = new osg::Vec4Array;
  shade->push_back(osg::Vec4(0.02f, 0.03f, 0.06f, 0.62f));
  panels_->setColorArray(shade.get(), osg::Array::BIND_OVERALL);
  panels_->setVertexArray(new osg::Vec3Array);
  panels_->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 0));

  figures_ = makeText(osgText::Text::LEFT_TOP);
  course_ = makeText(osgText::Text::RIGHT_TOP);
  message_ = makeText(osgText::Text::CENTER_BOTTOM);
  menu_ = makeText(osgText::Text::LEFT_CENTER);
  gg_ = std::make_unique<GgDiagram>(font_.get());
  osg::ref_ptr<osg::Geode> geode = new osg::Geode;
  geode->addDrawable(panels_.get());
  geode->addDrawable(figures_.get());
  geode->addDrawable(course_.get());
  geode->addDrawable(message_.get());
  geode->addDrawable(menu_.get());
  camera_->addChild(geode);
  camera_->addChild(gg_->node());  // after the panels: drawn over its own
  layout(1280, 720);
}

void HudNode::setTrackMap(const std::vector<Eigen::Vector2d>& line) {
  map_ = std::make_unique<TrackMap>(line);
  camera_->addChild(map_->node());
  const int w = width_, h = height_;
  width_ = 0;  // its panel joins the others
  layout(w, h);
}

// A dynamic white text block with the HUD font.
osg::ref_ptr<osgText::Text> HudNode::makeText(osgText::Text::AlignmentType align) {
  osg::ref_ptr<osgText::Text> t = new osgText::Text;
  t->setDataVariance(osg::Object::DYNAMIC);
  t->setFont(font_.get());
  t->setAlignment(align);
  t->setColor(osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f));
  t->setLineSpacing(0.18f);
  t->setCharacterSizeMode(osgText::Text::OBJECT_COORDS);
  return t;
}

// osgText re-lays out glyphs on every setText: skip it when nothing changed.
void HudNode::setIfChanged(osgText::Text& text, const std::string& value) {
  if (text.getText().createUTF8EncodedString() != value) text.setText(value, osgText::String::ENCODING_UTF8);
}

// Formats the figures; course and message panels only appear when they have content.
void HudNode::update(const vehicle::HudInfo& hud, CameraMode camera, BodyDisplay body) {
  const char* deg = unicode_ ? "\u00b0" : " deg";
  const char* accel = unicode_ ? "m/s\u00b2" : "m/s^2";
  std::string fig = format("%6.1f km/h\n", hud.speed * 3.6);
  fig += format("steer %+7.1f%s\n", hud.steeringWheelAngle * 180.0 / M_PI, deg);
  fig += format("a_y   %+6.2f %s\n", hud.lateralAcceleration, accel);
  fig += format("yaw   %+6.1f%s/s\n", hud.yawRate * 180.0 / M_PI, deg);
  fig += format("%-6s%6.2f x\n", hud.realTimeLabel.c_str(), hud.realTimeFactor);
  fig += format("step  %6.0f us\n", hud.stepTime * 1e6);
  // A speed hold drives the wheels without the throttle: say what it holds.
  if (hud.speedHold >= 0)
    fig += format("hold %3.0f km/h brk %3.0f%%", hud.speedHold * 3.6, 100 * std::clamp(hud.brake, 0.0, 1.0));
  else
    fig += format("thr %3.0f%%  brk %3.0f%%", 100 * std::clamp(hud.throttle, 0.0, 1.0), 100 * std::clamp(hud.brake, 0.0, 1.0));
  if (hud.powertrain) {
    const std::string gear = hud.gear < 0 ? "R" : hud.gear == 0 ? "N" : std::to_string(hud.gear);
    fig += format("\ngear %-2s%s %5.0f rpm%s", gear.c_str(), hud.shifting ? ">" : " ", hud.engineRpm,
                  hud.handbrake > 0.05 ? " HB" : "");
  }
  setIfChanged(*figures_, fig);
  gg_->update(hud.time, hud.longitudinalAcceleration, hud.lateralAcceleration);
  if (map_) map_->update(hud.mapX, hud.mapY, hud.mapYaw);
  const int figureLines = hud.powertrain ? kFigureLines + 1 : kFigureLines;
  if (figureLines != figureLines_) {
    figureLines_ = figureLines;
    const int w = width_, h = height_;
    width_ = 0;  // the figures' panel grows by a line
    layout(w, h);
  }

  std::string right = format("t %7.2f s\n%s", hud.time, cameraName(camera));
  if (body != BodyDisplay::Solid) right += format(" / body %s", bodyDisplayName(body));
  if (!hud.model.empty()) right += "\nmodel " + hud.model;
  if (body != BodyDisplay::Solid && !hud.members.empty()) right += "\n" + hud.members;
  if (hud.coneHits >= 0) right += format("\ncones hit %d", hud.coneHits);
  if (hud.courseTime >= 0) right += format("\ncourse %6.2f s", hud.courseTime);
  if (!hud.verdict.empty()) right += "\n" + hud.verdict;
  if (hud.lap == 0) right += "\nout lap";
  if (hud.lap > 0)
    right += format("\nlap %d S%d %s%s", hud.lap, hud.sector, scenario::lapClock(hud.lapTime).c_str(),
                    hud.lapValid ? "" : " cut");
  if (hud.lapDeltaShown) right += format("\ndelta %+.2f s", hud.lapDelta);
  if (hud.lastLap >= 0) right += "\nlast " + scenario::lapClock(hud.lastLap);
  if (hud.bestLap >= 0) right += "\nbest " + scenario::lapClock(hud.bestLap);
  setIfChanged(*course_, right);
  setIfChanged(*message_, hud.message);
  setIfChanged(*menu_, hud.menu);
  int menuLines = 0, menuColumns = 0;
  if (!hud.menu.empty()) {
    menuLines = 1;
    for (std::size_t start = 0; start <= hud.menu.size();) {
      const std::size_t end = std::min(hud.menu.find('\n', start), hud.menu.size());
      menuColumns = std::max(menuColumns, static_cast<int>(end - start));
      if (end < hud.menu.size()) ++menuLines;
      start = end + 1;
    }
  }
  if (menuLines != menuLines_ || menuColumns != menuColumns_) {
    menuLines_ = menuLines;
    menuColumns_ = menuColumns;
    const int w = width_, h = height_;
    width_ = 0;  // the menu's panel opens, closes or changes size
    layout(w, h);
  }

  const bool showMessage = !hud.message.empty();
  const int courseLines = 1 + static_cast<int>(std::count(right.begin(), right.end(), '\n'));
  // The panel as wide as its longest line (the verdict's may be), 18 columns at least.
  int courseColumns = 18;
  for (std::size_t start = 0; start <= right.size();) {
    const std::size_t end = std::min(right.find('\n', start), right.size());
    courseColumns = std::max(courseColumns, static_cast<int>(end - start));
    start = end + 1;
  }
  if (showMessage != showMessage_ || courseLines != courseLines_ || courseColumns != courseColumns_) {
    showMessage_ = showMessage;
    courseLines_ = courseLines;
    courseColumns_ = courseColumns;
    const int w = width_, h = height_;
    width_ = 0;  // force the panels to be rebuilt
    layout(w, h);
  }
  useBilinearGlyphs(*font_);
}

// Character size follows the window height so the HUD reads the same at any size.
void HudNode::layout(int width, int height) {
  if (width == width_ && height == height_) return;
  width_ = width;
  height_ = height;
  camera_->setProjectionMatrix(osg::Matrix::ortho2D(0, width, 0, height));
  const float size = std::clamp(height / 34.0f, 10.0f, 26.0f), margin = 0.6f * size, pad = 0.4f * size;
  const float lineHeight = size * 1.18f, charWidth = size * 0.6f;
  // Glyphs rasterised at the size they are drawn: sampled one texel per pixel.
  const unsigned fontPixels = static_cast<unsigned>(std::lround(size));
  for (osgText::Text* t : {figures_.get(), course_.get(), message_.get()}) {
    t->setCharacterSize(size);
    t->setFontResolution(fontPixels, fontPixels);
  }
  // The menu smaller, so that it fits between the side panels.
  const float menuSize = 0.75f * size, menuLineHeight = menuSize * 1.18f, menuCharWidth = menuSize * 0.63f;
  const unsigned menuPixels = static_cast<unsigned>(std::lround(menuSize));
  menu_->setCharacterSize(menuSize);
  menu_->setFontResolution(menuPixels, menuPixels);
  figures_->setPosition(osg::Vec3(margin + pad, height - margin - pad, 0));
  course_->setPosition(osg::Vec3(width - margin - pad, height - margin - pad, 0));
  message_->setPosition(osg::Vec3(width / 2.0f, margin + pad, 0));
  // The menu in the middle, as wide as its longest line (at most the window).
  const float menuHalf = std::min(0.49f * width, 0.5f * menuCharWidth * float(menuColumns_) + pad);
  menu_->setPosition(osg::Vec3(width / 2.0f - menuHalf + pad, height / 2.0f, 0));

  osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
  addRect(*v, margin, height - margin - 2 * pad - figureLines_ * lineHeight, margin + 2 * pad + kFigureColumns * charWidth,
          height - margin);
  addRect(*v, width - margin - 2 * pad - float(courseColumns_) * charWidth, height - margin - 2 * pad - courseLines_ * lineHeight,
          width - margin, height - margin);
  if (menuLines_ > 0) {
    const float half = 0.5f * menuLines_ * menuLineHeight + pad;
    addRect(*v, width / 2.0f - menuHalf, height / 2.0f - half, width / 2.0f + menuHalf, height / 2.0f + half);
  }
  if (showMessage_) {
    const float half = std::min(0.48f * width, 0.5f * charWidth * float(message_->getText().size()) + pad);
    addRect(*v, width / 2.0f - half, margin, width / 2.0f + half, margin + 2 * pad + lineHeight);
  }
  // The g-g diagram bottom left, above the message line's band (a long verdict
  // reaches that far): its 1 g ring a tenth of the height across in radius.
  const float ggRadius = 0.1f * height, ggHalf = GgDiagram::kClampG * ggRadius + pad;
  const float ggLeft = margin, ggBottom = 2 * margin + 2 * pad + lineHeight;
  addRect(*v, ggLeft, ggBottom, ggLeft + 2 * ggHalf, ggBottom + 2 * ggHalf);
  gg_->layout(ggLeft + ggHalf, ggBottom + ggHalf, ggRadius, 0.7f * size);
  if (map_) {
    // The track map bottom right, as tall as the g-g panel.
    const float side = 2 * ggHalf, x0 = width - margin - side;
    addRect(*v, x0, ggBottom, x0 + side, ggBottom + side);
    map_->layout(x0, ggBottom, side);
  }
  useBilinearGlyphs(*font_);  // glyphs at a new resolution may open a new texture
  panels_->setVertexArray(v.get());
  static_cast<osg::DrawArrays*>(panels_->getPrimitiveSet(0))->setCount(static_cast<GLsizei>(v->size()));
  panels_->dirtyBound();
}

}  // namespace bdfcar::render
