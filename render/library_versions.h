// The window's and renderer's library versions as `bdfcar version` prints
// them: the one the build compiled against and, where the library can say,
// the one loaded now (a distribution update changes the shared library).
#pragma once

#include <string>

namespace bdfcar::render {

std::string osgVersion();  // "OpenSceneGraph 3.6.5"
std::string sdlVersion();  // "SDL2 2.26.5 (compiled against 2.26.5)"; in the window library

}  // namespace bdfcar::render
