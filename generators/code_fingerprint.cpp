#include "generators/code_fingerprint.hpp"

#include <stdexcept>

#include "brdftab_code_fingerprints.h"  // BRDFTAB_CODE_FINGERPRINTS(X), written at build time

namespace brdftab::gen {

namespace {

const std::map<std::string, std::string>& built_in() {
  static const std::map<std::string, std::string> m = {
#define BRDFTAB_FINGERPRINT_ENTRY(K, fp) {#K, fp},
      BRDFTAB_CODE_FINGERPRINTS(BRDFTAB_FINGERPRINT_ENTRY)
#undef BRDFTAB_FINGERPRINT_ENTRY
  };
  return m;
}

const std::map<std::string, std::string>* g_replaced = nullptr;

}  // namespace

std::string code_fingerprint(const std::string& family) {
  if (g_replaced)
    if (auto it = g_replaced->find(family); it != g_replaced->end()) return it->second;
  const auto it = built_in().find(family);
  if (it == built_in().end()) throw std::invalid_argument("code_fingerprint: '" + family + "' is not a table family");
  return it->second;
}

ScopedCodeFingerprints::ScopedCodeFingerprints(std::map<std::string, std::string> replaced) {
  if (g_replaced) throw std::logic_error("ScopedCodeFingerprints: one at a time");
  g_replaced = new std::map<std::string, std::string>(std::move(replaced));
}

ScopedCodeFingerprints::~ScopedCodeFingerprints() {
  delete g_replaced;
  g_replaced = nullptr;
}

}  // namespace brdftab::gen
