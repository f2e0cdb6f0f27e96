#pragma once
// Bytes as base64 text (RFC 4648, with padding): how a web page or a report carries a picture or
// packed data inside itself.
#include <cstddef>
#include <string>

namespace dinam {

std::string base64(const void* bytes, std::size_t size);

}  // namespace dinam
