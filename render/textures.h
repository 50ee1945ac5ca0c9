// Private to render/: procedural, tileable textures (no image files needed).
#pragma once

#include <osg/Texture2D>

namespace bdfcar::render {

// Mottled grass, 256x256, repeating.
osg::ref_ptr<osg::Texture2D> grassTexture();
// Fine-grained asphalt, 256x256, repeating.
osg::ref_ptr<osg::Texture2D> asphaltTexture();

}  // namespace bdfcar::render
