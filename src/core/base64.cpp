#include "core/base64.hpp"

#include <cstdint>

namespace dinam {

std::string base64(const void* bytes, std::size_t size) {
  const auto* data = static_cast<const unsigned char*>(bytes);
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve(4 * ((size + 2) / 3));
  for (std::size_t i = 0; i < size; i += 3) {
    const std::uint32_t chunk = (std::uint32_t{data[i]} << 16) |
                                (i + 1 < size ? std::uint32_t{data[i + 1]} << 8 : 0u) |
                                (i + 2 < size ? std::uint32_t{data[i + 2]} : 0u);
    out.push_back(kDigits[(chunk >> 18) & 63]);
    out.push_back(kDigits[(chunk >> 12) & 63]);
    out.push_back(i + 1 < size ? kDigits[(chunk >> 6) & 63] : '=');
    out.push_back(i + 2 < size ? kDigits[chunk & 63] : '=');
  }
  return out;
}

}  // namespace dinam
