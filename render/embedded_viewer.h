// Private to render/: an OSG viewer drawing the scene into a GL context that
// someone else made current (SDL window or OSMesa buffer); single-threaded.
#pragma once

#include <osgViewer/Viewer>

#include "render/frame.h"
#include "render/scene_impl.h"

namespace bdfcar::render {

// Viewer embedded in the current context, sun-lit, clearing to the horizon colour.
osg::ref_ptr<osgViewer::Viewer> makeEmbeddedViewer(Scene::Impl& scene, int width, int height);

// Draws one frame of the scene at width x height into the current context.
void drawFrame(osgViewer::Viewer& viewer, Scene::Impl& scene, int width, int height);

// What the last frame drew: its drawables and triangles (OSG's statistics
// of the render stage the cull produced). A count, steadier than the draw's
// milliseconds on a shared machine.
DrawLoad lastDrawLoad(osgViewer::Viewer& viewer);

// Releases the viewer's GL objects while its context is still current (so a
// later context reusing the same OSG context id starts clean).
void releaseViewer(osgViewer::Viewer& viewer);

}  // namespace bdfcar::render
