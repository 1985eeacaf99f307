#include "lookup/shipped_tables.hpp"

namespace brdftab::lookup {

namespace {
constexpr ShippedTable kShipped[] = {
#include BRDFTAB_SHIPPED_TABLES_INC
    {nullptr, nullptr}};
}  // namespace

std::span<const ShippedTable> shipped_tables() { return {kShipped, std::size(kShipped) - 1}; }

std::optional<std::string> shipped_table_sha256(std::string_view file_name) {
  for (const auto& t : shipped_tables())
    if (file_name == t.file) return std::string(t.sha256);
  return std::nullopt;
}

}  // namespace brdftab::lookup
