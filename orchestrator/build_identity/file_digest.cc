#include "orchestrator/build_identity/file_digest.h"

#include <dlfcn.h>
#include <fmt/format.h>
#include <openssl/evp.h>
#include <openssl/opensslv.h>

#include <array>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::orchestrator::inline build_identity {
namespace {

// OpenSSL's libcrypto is loaded when the first digest is taken, not at program start: its ~21,000
// relocations were two thirds of the core program's start-up (`slamsweep --version`), which never
// takes a digest. The functions are the same ones a link would bind.
struct Crypto {
  decltype(&EVP_MD_CTX_new) md_ctx_new = nullptr;
  decltype(&EVP_MD_CTX_free) md_ctx_free = nullptr;
  decltype(&EVP_sha256) sha256 = nullptr;
  decltype(&EVP_DigestInit_ex) digest_init = nullptr;
  decltype(&EVP_DigestUpdate) digest_update = nullptr;
  decltype(&EVP_DigestFinal_ex) digest_final = nullptr;
};

// The soname of the major version the headers are from (libcrypto.so.3 for OpenSSL 3.x).
std::string LibcryptoSoname() { return fmt::format("libcrypto.so.{}", OPENSSL_VERSION_MAJOR); }

template <typename Function>
void Bind(void* library, const char* name, Function& function) {
  function = reinterpret_cast<Function>(::dlsym(library, name));
  if (function == nullptr) throw std::runtime_error(fmt::format("OpenSSL: {} has no {}", LibcryptoSoname(), name));
}

Crypto LoadCrypto() {
  const std::string soname = LibcryptoSoname();
  void* library = ::dlopen(soname.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) {
    const char* reason = ::dlerror();
    throw std::runtime_error(fmt::format("OpenSSL: cannot load {} for SHA-256 digests: {}", soname,
                                         reason != nullptr ? reason : "unknown reason"));
  }
  Crypto crypto;
  Bind(library, "EVP_MD_CTX_new", crypto.md_ctx_new);
  Bind(library, "EVP_MD_CTX_free", crypto.md_ctx_free);
  Bind(library, "EVP_sha256", crypto.sha256);
  Bind(library, "EVP_DigestInit_ex", crypto.digest_init);
  Bind(library, "EVP_DigestUpdate", crypto.digest_update);
  Bind(library, "EVP_DigestFinal_ex", crypto.digest_final);
  return crypto;  // the library stays loaded for the life of the program
}

const Crypto& Libcrypto() {
  static const Crypto crypto = LoadCrypto();
  return crypto;
}

struct DigestContextFree {
  void operator()(EVP_MD_CTX* context) const { Libcrypto().md_ctx_free(context); }
};
using DigestContext = std::unique_ptr<EVP_MD_CTX, DigestContextFree>;

DigestContext StartSha256() {
  const Crypto& crypto = Libcrypto();
  DigestContext context(crypto.md_ctx_new());
  if (!context || crypto.digest_init(context.get(), crypto.sha256(), nullptr) != 1) {
    throw std::runtime_error("OpenSSL: cannot start a SHA-256 digest");
  }
  return context;
}

std::string FinishHex(EVP_MD_CTX* context) {
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int length = 0;
  if (Libcrypto().digest_final(context, digest.data(), &length) != 1) {
    throw std::runtime_error("OpenSSL: cannot finish a SHA-256 digest");
  }
  std::string hex;
  hex.reserve(2 * length);
  for (unsigned int i = 0; i < length; ++i) hex += fmt::format("{:02x}", digest[i]);
  return hex;
}

}  // namespace

std::string Sha256OfBytes(std::string_view bytes) {
  const DigestContext context = StartSha256();
  Libcrypto().digest_update(context.get(), bytes.data(), bytes.size());
  return FinishHex(context.get());
}

std::string Sha256OfFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw evaluator::InputError(file.string() + ": cannot read the file to compute its digest");
  const DigestContext context = StartSha256();
  const Crypto& crypto = Libcrypto();
  std::array<char, 1 << 16> buffer{};
  while (in) {
    in.read(buffer.data(), buffer.size());
    if (in.gcount() > 0) crypto.digest_update(context.get(), buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw evaluator::InputError(file.string() + ": read error while computing its digest");
  return FinishHex(context.get());
}

}  // namespace slamsweep::orchestrator::inline build_identity
