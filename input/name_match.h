// Device-name matching shared by mapping selection and the device filter (private to input/).
#pragma once

#include <string_view>

namespace bdfcar::input {

// Whether `needle` occurs in `haystack`, ignoring ASCII case.
bool containsNoCase(std::string_view haystack, std::string_view needle);

}  // namespace bdfcar::input
