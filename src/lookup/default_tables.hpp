#pragma once
// Where the lookup library and the CLI look for tables when no folder is given:
//  1. the BRDFTAB_TABLES environment variable, if set and non-empty;
//  2. the installed default tables, <prefix>/share/brdftab/tables: found relative to the
//     installed library's folder (so `cmake --install --prefix P` and moved installations
//     work), else the path configured at build time.
// Callers that want another folder pass it explicitly (e.g. TableSet("my/tables")).
#include <filesystem>

namespace brdftab::lookup {

std::filesystem::path default_tables_dir();
// The install location compiled into the library (may not exist).
std::filesystem::path installed_tables_dir();

}  // namespace brdftab::lookup
