#pragma once
// SHA-256 content hashes (OpenSSL's libcrypto), as 64 lower-case hex digits: the same text
// `sha256sum` prints, so a user can check a hash a motion cache records.
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace dinam {

class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;

  void update(const void* data, std::size_t size);
  void update(std::string_view text) { update(text.data(), text.size()); }
  // The digest of everything given so far; the hash cannot be updated afterwards.
  std::string hex_digest();

 private:
  struct Context;
  std::unique_ptr<Context> context_;
};

std::string sha256_hex(std::string_view bytes);

}  // namespace dinam
