#include "render/library_versions.h"

#include <osg/Version>

namespace bdfcar::render {

std::string osgVersion() { return std::string("OpenSceneGraph ") + osgGetVersion(); }

}  // namespace bdfcar::render
