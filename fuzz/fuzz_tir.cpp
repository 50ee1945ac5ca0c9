// The .tir reader and the PAC2002 coefficients it yields (physics/tyre/
// tir_file.h, pac2002_file.h): a file accepted in either evaluation must
// give finite forces over the slips and loads a tyre meets.
#include <cmath>

#include "fuzz_common.h"
#include "tyre/pac2002_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = bdfcar::fuzz::writeCase(data, size, "tyre.tir");
  for (auto variant : {bdfcar::tyre::Pac2002Variant::Textbook, bdfcar::tyre::Pac2002Variant::Chrono9}) {
    try {
      const bdfcar::tyre::Pac2002Params p = bdfcar::tyre::readPac2002(path, variant).params;
      for (double Fz : {0.3 * p.nominalLoad, p.nominalLoad, 2.0 * p.nominalLoad})
        for (double s : {-0.3, -0.02, 0.0, 0.05, 0.5}) {
          const auto f = bdfcar::tyre::magicFormula(p, s, 0.7 * s, 0.0, Fz, 0.8, 20.0);
          if (!std::isfinite(f.Fx) || !std::isfinite(f.Fy) || !std::isfinite(f.Mz)) __builtin_trap();
        }
    } catch (const bdfcar::tyre::TirError&) {
      // documented: a message naming the file, line and key
    }
  }
  return 0;
}
