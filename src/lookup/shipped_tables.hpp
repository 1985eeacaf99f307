#pragma once
// The table files the project ships (tables/*.h5 at build time), each with the SHA-256 of
// the whole file, compiled into the library: a shipped table someone modified and
// re-sealed (its own digest then matches) is still told apart from the one shipped.
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace brdftab::lookup {

struct ShippedTable {
  const char* file;    // e.g. "demo.h5"
  const char* sha256;  // lowercase hex of the whole file
};
std::span<const ShippedTable> shipped_tables();
// The recorded SHA-256 of the shipped file of that name, if there is one.
std::optional<std::string> shipped_table_sha256(std::string_view file_name);

}  // namespace brdftab::lookup
