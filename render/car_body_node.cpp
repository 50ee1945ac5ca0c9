#include <osg/BlendColor>
#include <osg/BlendFunc>
#include <osg/CullFace>
#include <osg/Depth>
#include <osg/Geode>
#include <osg/LineWidth>
#include <osg/Material>

#include <cstdio>
#include <filesystem>
#include <utility>

#include "render/car_nodes.h"
#include "render/obj_mesh.h"
#include "render/osg_convert.h"

namespace bdfcar::render {
namespace {

// Colour of an OBJ material name; "paint" is the vehicle's body colour.
osg::Vec4 materialColour(const std::string& name, const osg::Vec4& paint) {
  if (name == "paint") return paint;
  if (name == "glass") return rgba(0.10, 0.13, 0.18);
  if (name == "trim") return rgba(0.07, 0.07, 0.08);
  if (name == "chrome") return rgba(0.72, 0.73, 0.76);
  if (name == "headlight") return rgba(1.0, 0.97, 0.86);
  if (name == "plate") return rgba(0.92, 0.92, 0.86);
  return rgba(0.55, 0.55, 0.55);
}

// The lamps' colours, off and on (unlit: what is drawn).
Lamp brakeLamp() { return Lamp{nullptr, rgba(0.42, 0.03, 0.03), rgba(1.0, 0.12, 0.08), false}; }
Lamp reverseLamp() { return Lamp{nullptr, rgba(0.55, 0.56, 0.58), rgba(1.0, 1.0, 1.0), false}; }

// Geode of all OBJ parts, flat-shaded unless the file gives normals; the
// lamps' parts ("taillight", "reverselight") each in a drawable of their own.
osg::ref_ptr<osg::Geode> geodeFromObj(const ObjMesh& mesh, const osg::Vec4& paint, BodyNode& out) {
  TriangleBuilder body, tail, reverse;
  for (const ObjPart& part : mesh.parts) {
    const bool isTail = part.material == "taillight", isReverse = part.material == "reverselight";
    TriangleBuilder& tb = isTail ? tail : isReverse ? reverse : body;
    const osg::Vec4 colour = isTail ? out.brakeLights.off : isReverse ? out.reverseLights.off
                                                                      : materialColour(part.material, paint);
    for (std::size_t i = 0; i + 2 < part.corners.size(); i += 3) {
      const osg::Vec3 a(part.corners[i].x(), part.corners[i].y(), part.corners[i].z());
      const osg::Vec3 b(part.corners[i + 1].x(), part.corners[i + 1].y(), part.corners[i + 1].z());
      const osg::Vec3 c(part.corners[i + 2].x(), part.corners[i + 2].y(), part.corners[i + 2].z());
      if (part.normals.empty()) {
        tb.triangle(a, b, c, colour);
      } else {
        for (int k = 0; k < 3; ++k) {
          const Eigen::Vector3f& n = part.normals[i + k];
          tb.vertex(k == 0 ? a : k == 1 ? b : c, osg::Vec3(n.x(), n.y(), n.z()), colour);
        }
      }
    }
  }
  osg::ref_ptr<osg::Geode> geode = new osg::Geode;
  geode->addDrawable(body.build());
  for (auto [tb, lamp] : {std::pair{&tail, &out.brakeLights}, std::pair{&reverse, &out.reverseLights}}) {
    if (tb->v->empty()) continue;
    lamp->geometry = tb->build();
    lamp->geometry->getOrCreateStateSet()->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
    geode->addDrawable(lamp->geometry.get());
  }
  return geode;
}

// Axis-aligned box between lo and hi, outward faces.
void addBox(TriangleBuilder& tb, const osg::Vec3& lo, const osg::Vec3& hi, const osg::Vec4& colour) {
  const osg::Vec3 p[8] = {{lo.x(), lo.y(), lo.z()}, {hi.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), lo.z()},
                          {lo.x(), hi.y(), lo.z()}, {lo.x(), lo.y(), hi.z()}, {hi.x(), lo.y(), hi.z()},
                          {hi.x(), hi.y(), hi.z()}, {lo.x(), hi.y(), hi.z()}};
  tb.quad(p[0], p[3], p[2], p[1], colour);
  tb.quad(p[4], p[5], p[6], p[7], colour);
  tb.quad(p[0], p[1], p[5], p[4], colour);
  tb.quad(p[1], p[2], p[6], p[5], colour);
  tb.quad(p[2], p[3], p[7], p[6], colour);
  tb.quad(p[3], p[0], p[4], p[7], colour);
}

// Fallback body: a painted lower box and a glass cabin, sized from the geometry.
osg::ref_ptr<osg::Geode> boxBody(const vehicle::VehicleGeometry& g, const osg::Vec4& paint) {
  const osg::Vec3 c = toOsgF(g.bodyOffset);
  const float l = float(g.length) / 2, w = float(g.width) / 2, h = float(g.height);
  TriangleBuilder tb;
  addBox(tb, c + osg::Vec3(-l, -w, -h / 2), c + osg::Vec3(l, w, 0.1f * h), paint);
  addBox(tb, c + osg::Vec3(-0.45f * l, -0.9f * w, 0.1f * h), c + osg::Vec3(0.3f * l, 0.9f * w, h / 2),
         materialColour("glass", paint));
  osg::ref_ptr<osg::Geode> geode = new osg::Geode;
  geode->addDrawable(tb.build());
  return geode;
}

// Glossy paint for the solid body.
osg::ref_ptr<osg::StateSet> solidState() {
  osg::ref_ptr<osg::StateSet> ss = new osg::StateSet;
  osg::ref_ptr<osg::Material> m = new osg::Material;
  m->setColorMode(osg::Material::AMBIENT_AND_DIFFUSE);
  m->setSpecular(osg::Material::FRONT_AND_BACK, osg::Vec4(0.45f, 0.45f, 0.45f, 1.0f));
  m->setShininess(osg::Material::FRONT_AND_BACK, 48.0f);
  ss->setAttributeAndModes(m.get());
  return ss;
}

// Whole body at 30 % opacity whatever its vertex colours: constant-alpha blending,
// no depth writes (the links behind stay visible), back faces culled to avoid clutter.
osg::ref_ptr<osg::StateSet> translucentState(const osg::StateSet& solid) {
  osg::ref_ptr<osg::StateSet> ss = new osg::StateSet(solid, osg::CopyOp::SHALLOW_COPY);
  ss->setAttributeAndModes(new osg::BlendColor(osg::Vec4(1, 1, 1, 0.3f)));
  ss->setAttributeAndModes(new osg::BlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA));
  ss->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, false));
  ss->setAttributeAndModes(new osg::CullFace(osg::CullFace::BACK));
  ss->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
  return ss;
}

// The chassis as a frame of lines, for the suspension views: the body's box
// (its 12 edges) with a ladder along its floor, so that roll and pitch read
// even with the body hidden. Unlit, in the chassis frame.
osg::ref_ptr<osg::Node> makeChassisFrame(const vehicle::VehicleGeometry& g) {
  const osg::Vec3 c = toOsgF(g.bodyOffset);
  const float l = float(g.length) / 2, w = float(g.width) / 2, lo = -float(g.height) / 2, hi = 0.1f * float(g.height);
  osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
  auto line = [&](const osg::Vec3& a, const osg::Vec3& b) {
    v->push_back(c + a);
    v->push_back(c + b);
  };
  for (float z : {lo, hi}) {
    line({-l, -w, z}, {l, -w, z});
    line({-l, w, z}, {l, w, z});
    line({-l, -w, z}, {-l, w, z});
    line({l, -w, z}, {l, w, z});
  }
  for (float x : {-l, l})
    for (float y : {-w, w}) line({x, y, lo}, {x, y, hi});
  // The ladder: two rails inside the sills and cross members.
  const float rail = 0.6f * w;
  line({-l, -rail, lo}, {l, -rail, lo});
  line({-l, rail, lo}, {l, rail, lo});
  for (float x : {-0.5f * l, 0.0f, 0.5f * l}) line({x, -w, lo}, {x, w, lo});
  osg::ref_ptr<osg::Geometry> geom = new osg::Geometry;
  geom->setVertexArray(v.get());
  osg::ref_ptr<osg::Vec4Array> colour = new osg::Vec4Array;
  colour->push_back(rgba(0.8, 0.6, 1.0));  // violet: no other part of the scene has it
  geom->setColorArray(colour.get(), osg::Array::BIND_OVERALL);
  geom->addPrimitiveSet(new osg::DrawArrays(GL_LINES, 0, static_cast<GLsizei>(v->size())));
  osg::ref_ptr<osg::Geode> geode = new osg::Geode;
  geode->addDrawable(geom.get());
  osg::StateSet* ss = geode->getOrCreateStateSet();
  ss->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
  ss->setAttributeAndModes(new osg::LineWidth(2.0f));
  return geode;
}

}  // namespace

// Tries the path as given, then under assetRoot, then under the source tree.
std::string resolveAssetPath(const std::string& path, const std::string& assetRoot) {
  namespace fs = std::filesystem;
  if (path.empty()) return "";
  std::vector<fs::path> candidates{fs::path(path)};
  if (fs::path(path).is_relative()) {
    if (!assetRoot.empty()) candidates.push_back(fs::path(assetRoot) / path);
#ifdef BDFCAR_SOURCE_DIR
    candidates.push_back(fs::path(BDFCAR_SOURCE_DIR) / path);
#endif
  }
  for (const fs::path& p : candidates) {
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) return p.string();
  }
  return "";
}

// Body from the OBJ asset, or the box fallback with a warning printed to stderr.
BodyNode makeBodyNode(const vehicle::VehicleGeometry& geometry, const std::string& assetRoot) {
  const osg::Vec4 paint = rgba(geometry.bodyColour.x(), geometry.bodyColour.y(), geometry.bodyColour.z());
  BodyNode body;
  body.node = new osg::Group;
  body.brakeLights = brakeLamp();
  body.reverseLights = reverseLamp();
  osg::ref_ptr<osg::Geode> geode;
  const std::string path = resolveAssetPath(geometry.bodyMesh, assetRoot);
  if (!geometry.bodyMesh.empty() && path.empty()) {
    body.warning = "body mesh '" + geometry.bodyMesh + "' not found: drawing a box";
  } else if (!path.empty()) {
    try {
      geode = geodeFromObj(loadObj(path), paint, body);
      body.source = path;
    } catch (const std::exception& e) {
      body.warning = std::string(e.what()) + ": drawing a box";
    }
  }
  if (!geode) {
    geode = boxBody(geometry, paint);
    body.source = "box";
  }
  if (!body.warning.empty()) std::fprintf(stderr, "bdfcar render: %s\n", body.warning.c_str());
  body.node->addChild(geode);
  body.frame = makeChassisFrame(geometry);
  body.frame->setNodeMask(0u);  // solid body first
  body.solid = solidState();
  body.translucent = translucentState(*body.solid);
  body.node->setStateSet(body.solid.get());
  return body;
}

void setLamp(Lamp& lamp, bool on) {
  if (!lamp.geometry || lamp.lit == on) return;
  lamp.lit = on;
  auto* colours = static_cast<osg::Vec4Array*>(lamp.geometry->getColorArray());
  for (osg::Vec4& c : *colours) c = on ? lamp.on : lamp.off;
  colours->dirty();
}

// Swaps the body's state set and visibility; the chassis frame shows when the body does not (fully).
void applyBodyDisplay(BodyNode& body, BodyDisplay display) {
  body.node->setNodeMask(display == BodyDisplay::Hidden ? 0u : ~0u);
  if (body.frame) body.frame->setNodeMask(display == BodyDisplay::Solid ? 0u : ~0u);
  body.node->setStateSet(display == BodyDisplay::Translucent ? body.translucent.get() : body.solid.get());
}

}  // namespace bdfcar::render
