// `brdftab seal FILE...`: recomputes the digest block of a table file someone edited on
// purpose (with h5py, say), so that brdftab reads it again. The file must already carry
// a digest block (a brdftab file). Sealing says nothing about the values:
// `brdftab verify FILE` re-measures them against the exact numerics.
#include <cstring>
#include <ostream>

#include "cli/commands.hpp"
#include "cli/csv.hpp"
#include "lookup/bounded_read.hpp"
#include "lookup/table_digest.hpp"
#include "lookup/table_file.hpp"
#include "tablewrite/atomic_write.hpp"

namespace brdftab::cli {

int run_seal(const std::vector<std::filesystem::path>& files, std::ostream& out, std::ostream& err) {
  int status = 0;
  for (const auto& file : files) {
    const std::string name = escape_control(file.string());
    try {
      std::string bytes = lookup::read_regular_file(file, lookup::kMaxTableFileBytes, "table file");
      const std::size_t magic = std::strlen(lookup::kDigestMagic);
      if (bytes.size() <= lookup::kDigestBlockBytes || bytes.compare(0, magic, lookup::kDigestMagic) != 0) {
        err << "brdftab seal: '" << name << "' has no brdftab digest block (not a brdftab table file): refused\n";
        status = std::max(status, 2);
        continue;
      }
      const auto* body = reinterpret_cast<const unsigned char*>(bytes.data()) + lookup::kDigestBlockBytes;
      const std::string block = lookup::make_digest_block({body, bytes.size() - lookup::kDigestBlockBytes});
      const bool was_valid = bytes.compare(0, block.size(), block) == 0;
      bytes.replace(0, block.size(), block);
      if (!was_valid) tablewrite::write_file_atomically(file, bytes);
      lookup::list_tables(file);  // it must now read as a table file
      out << name << ": " << (was_valid ? "already sealed" : "sealed")
          << " (run `brdftab verify` to re-measure its values)\n";
    } catch (const std::exception& e) {
      err << "brdftab seal: " << escape_control(e.what()) << "\n";
      status = std::max(status, 1);
    }
  }
  return status;
}

}  // namespace brdftab::cli
