// A PAC2002 tyre from its .tir file (tyre/tir_file.h): the [MODEL] switches,
// dimensions and vertical data in SI, every coefficient of
// pac2002_coefficients.h (absent: 0, scaling factors 1), and checks that the
// curves are physical (positive shape and peak factors over the load range,
// slip stiffnesses of the right sign). Keys bdfcar does not evaluate are
// listed in `ignoredKeys` for the loader to warn about; nothing unknown is
// read as a silent zero. Errors are TirError naming the file, line and key.
#pragma once

#include <string>

#include "tyre/pac2002.h"
#include "tyre/tir_file.h"

namespace bdfcar::tyre {

struct Pac2002File {
  Pac2002Params params;     // mountedLeft left true: the vehicle loader sets the side
  std::string ignoredKeys;  // "KEY (line N), ..." or empty
};

Pac2002File readPac2002(const TirFile& tir, Pac2002Variant variant);
Pac2002File readPac2002(const std::string& path, Pac2002Variant variant);

}  // namespace bdfcar::tyre
