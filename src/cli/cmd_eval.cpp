// `brdftab eval QUANTITY [--method exact|table|fit] [--tables DIR] < in.csv > out.csv`
//
// Every row is read and checked before any is computed, and output is written only when
// every row succeeded: a bad row never leaves a partial CSV on stdout. Rows are checked and
// computed in parallel (OpenMP) and printed in input order; memory does not grow with the
// number of rows:
//  1. Check: rows are read in chunks of kChunkRows, checked in parallel (cell count,
//     numbers, domains), and each checked row is appended compactly to an input spool: its
//     line number, its parameter values (binary doubles) and its input columns as they will
//     be printed. The first bad row in input order stops eval before anything is computed.
//  2. Compute: the spool is read back chunk by chunk, the rows are computed in parallel and
//     their output lines appended, in order, to an output spool. A row whose method throws
//     stops eval with nothing printed; when all succeeded, the output spool goes to stdout.
// A spool keeps up to kSpoolMemory bytes in memory (environment variables
// BRDFTAB_EVAL_SPOOL_BYTES and BRDFTAB_EVAL_CHUNK_ROWS override the spool memory and the
// chunk size; tests use them to exercise the file path and chunk boundaries) and
// continues in an anonymous temporary file (std::tmpfile: unique to this run, removed when
// eval ends), so memory stays below about 2 kSpoolMemory + a chunk whatever the row count,
// and small inputs touch no file.
// The header may be of any width and rows of any length: each is handled in linear time
// (columns are matched through a hash map).
#include <omp.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "cli/commands.hpp"
#include "cli/csv.hpp"
#include "cli/quantity.hpp"
#include "cli/deprecation.hpp"
#include "lookup/number_format.hpp"
#include "lookup/table_set.hpp"

namespace brdftab::cli {

namespace {

constexpr std::size_t kChunkRows = 65536;
constexpr std::size_t kSpoolMemory = std::size_t(8) << 20;

std::size_t spool_memory() {
  if (const char* v = std::getenv("BRDFTAB_EVAL_SPOOL_BYTES")) return std::strtoull(v, nullptr, 10);
  return kSpoolMemory;
}
std::size_t chunk_rows() {
  if (const char* v = std::getenv("BRDFTAB_EVAL_CHUNK_ROWS")) return std::max<std::size_t>(1, std::strtoull(v, nullptr, 10));
  return kChunkRows;
}

std::string list(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}

// Appends v as lookup::format_number(v) does (std::to_chars, shortest round-trip), without
// a temporary string.
void append_number(std::string& s, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, r.ptr);
}

// Append-only byte store: memory up to a limit, then an anonymous temporary file.
class Spool {
 public:
  explicit Spool(std::size_t memory_limit) : limit_(memory_limit) {}
  ~Spool() {
    if (file_) std::fclose(file_);
  }
  Spool(const Spool&) = delete;
  Spool& operator=(const Spool&) = delete;

  void write(const void* p, std::size_t n) {
    if (!file_ && mem_.size() + n <= limit_) {
      mem_.append(static_cast<const char*>(p), n);
      return;
    }
    if (!file_) {
      file_ = std::tmpfile();
      if (!file_) throw std::runtime_error(std::string("cannot create a temporary file: ") + std::strerror(errno));
      put(mem_.data(), mem_.size());
      std::string().swap(mem_);
    }
    put(p, n);
  }
  template <class T>
  void write_value(const T& v) {
    write(&v, sizeof v);
  }
  bool spilled() const { return file_ != nullptr; }
  // Switches to reading from the start.
  void rewind() {
    pos_ = 0;
    if (file_ && (std::fflush(file_) != 0 || std::fseek(file_, 0, SEEK_SET) != 0))
      throw std::runtime_error(std::string("temporary file: ") + std::strerror(errno));
  }
  void read(void* p, std::size_t n) {
    if (file_) {
      if (std::fread(p, 1, n, file_) != n) throw std::runtime_error("temporary file: short read");
    } else {
      if (pos_ + n > mem_.size()) throw std::logic_error("spool: read past the end");
      std::memcpy(p, mem_.data() + pos_, n);
      pos_ += n;
    }
  }
  template <class T>
  T read_value() {
    T v;
    read(&v, sizeof v);
    return v;
  }
  void copy_to(std::ostream& out) {
    if (!file_) {
      out.write(mem_.data(), static_cast<std::streamsize>(mem_.size()));
      return;
    }
    rewind();
    std::vector<char> buf(std::size_t(1) << 20);
    for (std::size_t got; (got = std::fread(buf.data(), 1, buf.size(), file_)) > 0;)
      out.write(buf.data(), static_cast<std::streamsize>(got));
  }

 private:
  void put(const void* p, std::size_t n) {
    if (n && std::fwrite(p, 1, n, file_) != n)
      throw std::runtime_error(std::string("cannot write a temporary file: ") + std::strerror(errno));
  }
  std::size_t limit_;
  std::string mem_;
  std::size_t pos_ = 0;
  std::FILE* file_ = nullptr;
};

// The longest CSV line (header or row) eval reads, and the most header columns: a line of
// 10^6 columns fits; past the cap, a clear error and exit 2 instead of memory exhaustion.
constexpr std::size_t kMaxCsvLineBytes = std::size_t(16) << 20;
constexpr std::size_t kMaxCsvColumns = std::size_t(1) << 21;
// The most bytes of raw lines one chunk of rows holds between the passes.
constexpr std::size_t kMaxChunkTextBytes = std::size_t(64) << 20;
struct LineTooLong {
  std::uint64_t line;
};

// Lines of a stream, read in blocks of 1 MiB (one istream::read per block instead of a
// locked character-by-character read of std::cin). A line ends at LF, CR LF or a lone CR
// (old Mac files); a UTF-8 byte order mark before the first line is dropped. Linear in
// the input length however long a line is.
class LineReader {
 public:
  explicit LineReader(std::istream& in) : in_(in) {}
  // Throws LineTooLong once a line passes kMaxCsvLineBytes (memory stays bounded).
  bool next(std::string& line) {
    while (true) {
      if (buf_.size() - pos_ > kMaxCsvLineBytes + 2 &&
          buf_.find_first_of("\r\n", pos_) == std::string::npos)
        throw LineTooLong(line_ + 1);
      const std::size_t nl = buf_.find_first_of("\r\n", scan_);
      // A CR at the end of the buffer may be the first half of CR LF: read on to decide.
      const bool undecided = nl != std::string::npos && buf_[nl] == '\r' && nl + 1 == buf_.size() && !eof_;
      if (nl != std::string::npos && !undecided) {
        line.assign(buf_, pos_, nl - pos_);
        std::size_t after = nl + 1;
        if (buf_[nl] == '\r' && after < buf_.size() && buf_[after] == '\n') ++after;
        pos_ = scan_ = after;
        if (line.size() > kMaxCsvLineBytes) throw LineTooLong(line_ + 1);
        return deliver(line);
      }
      if (eof_) {
        if (pos_ == buf_.size()) return false;
        line.assign(buf_, pos_);
        pos_ = scan_ = buf_.size();
        if (line.size() > kMaxCsvLineBytes) throw LineTooLong(line_ + 1);
        return deliver(line);
      }
      buf_.erase(0, pos_);
      scan_ = undecided ? nl - pos_ : buf_.size();
      pos_ = 0;
      const std::size_t old = buf_.size();
      buf_.resize(old + kBlock);
      in_.read(buf_.data() + old, kBlock);
      const std::size_t got = static_cast<std::size_t>(in_.gcount());
      buf_.resize(old + got);
      if (got < kBlock) eof_ = true;
    }
  }

 private:
  bool deliver(std::string& line) {
    ++line_;
    if (first_ && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
    first_ = false;
    return true;
  }
  static constexpr std::size_t kBlock = std::size_t(1) << 20;
  bool first_ = true;
  std::uint64_t line_ = 0;  // lines delivered
  std::istream& in_;
  std::string buf_;
  std::size_t pos_ = 0, scan_ = 0;  // start of the next line; where the newline search resumes
  bool eof_ = false;
};

// One chunk of rows between the passes.
struct Chunk {
  std::vector<std::string> text;     // pass 1: the raw lines; pass 2: the printed input columns
  std::vector<std::uint64_t> line;   // physical line numbers (blank lines are skipped)
  std::vector<double> inputs;        // rows x parameters
  std::vector<std::string> problem;  // pass 1/2: why a row failed (empty if it did not)
  std::size_t rows = 0;
};

}  // namespace

int run_eval(const EvalOptions& o, std::istream& in, std::ostream& out, std::ostream& err) {
  const Quantity* q = find_quantity(current_name(names::Kind::quantity, o.quantity, err));
  if (!q) {
    std::vector<std::string> names;
    for (const auto& x : all_quantities()) names.push_back(x.name);
    err << "brdftab eval: unknown quantity '" << escape_control(o.quantity.substr(0, 200)) << "' (known: " << list(names) << ")\n";
    return 2;
  }
  // `--dataset` naming a per-material table: q for that material (eval_material.cpp).
  std::optional<Quantity> material;
  if (!o.dataset.empty() && o.method == "table") {
    try {
      material = material_quantity(*q, o.tables_dir, o.dataset);
    } catch (const std::exception& e) {
      err << "brdftab eval " << q->name << " --dataset " << escape_control(o.dataset) << ": " << e.what() << "\n";
      return 2;
    }
    if (material) q = &*material;
  }
  auto method_it = q->methods.find(o.method);
  if (method_it == q->methods.end()) {
    std::vector<std::string> names;
    for (const auto& [k, v] : q->methods) names.push_back(k);
    err << "brdftab eval " << q->name << ": no method '" << escape_control(o.method.substr(0, 200)) << "' for this quantity (available: "
        << list(names) << ")\n";
    return 2;
  }
  const Method& method = method_it->second;
  if (!o.dataset.empty() && o.method != "table") {
    err << "brdftab eval " << q->name << ": --dataset needs --method table\n";
    return 2;
  }
  std::vector<std::string> param_names;
  for (const auto& p : q->parameters) param_names.push_back(p.name);
  const std::string what = "brdftab eval " + q->name;

  LineReader reader(in);
  std::string line;
  auto too_long = [&](const LineTooLong& e) {
    err << what << ": line " << e.line << " is longer than " << kMaxCsvLineBytes
        << " bytes (the limit for a CSV line or header): refused\n";
    return 2;
  };
  bool have_header = false;
  try {
    have_header = reader.next(line);
  } catch (const LineTooLong& e) {
    return too_long(e);
  }
  if (!have_header) {
    err << what << ": empty input; expected a CSV header naming the columns " << list(param_names) << "\n";
    return 2;
  }
  auto header = split_csv_line(line, kMaxCsvColumns + 1);
  if (header.size() > kMaxCsvColumns) {
    err << what << ": header (line 1): more than " << kMaxCsvColumns << " columns: refused\n";
    return 2;
  }
  for (const auto& h : header)
    if (h.size() > 4096) {
      err << what << ": header (line 1): a column name is longer than 4096 bytes: refused\n";
      return 2;
    }
  for (auto& h : header) h = current_name(names::Kind::column, h, err);
  const std::size_t ncol = header.size(), np = q->parameters.size();
  std::unordered_map<std::string_view, std::size_t> column_by_name;
  column_by_name.reserve(ncol);
  for (std::size_t c = 0; c < ncol; ++c)
    if (!column_by_name.emplace(header[c], c).second) {
      err << what << ": header (line 1): column '" << escape_control(header[c]) << "' appears twice\n";
      return 2;
    }
  // column_of[i] = kAbsent: an optional parameter without a column (its fallback is used).
  constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);
  // An input column named like an output column would appear twice in the output.
  for (const auto& name : q->outputs)
    if (column_by_name.count(name)) {
      std::string outputs;
      for (const auto& o : q->outputs) outputs += (outputs.empty() ? "" : ", ") + o;
      err << what << ": header (line 1): input column '" << escape_control(name)
          << "' has the name of an output column (outputs: " << outputs << "); rename or drop that input column\n";
      return 2;
    }
  std::vector<std::size_t> column_of(np);
  std::vector<int> param_of_column(ncol, -1);
  for (std::size_t i = 0; i < np; ++i) {
    const auto it = column_by_name.find(q->parameters[i].name);
    if (it == column_by_name.end() && q->parameters[i].fallback) {
      column_of[i] = kAbsent;
      continue;
    }
    if (it == column_by_name.end()) {
      err << what << ": header (line 1): missing column '" << q->parameters[i].name
          << "' (this quantity needs columns " << list(param_names) << "; got "
          << escape_control(list(header).substr(0, 400)) << ")\n";
      return 2;
    }
    column_of[i] = it->second;
    param_of_column[it->second] = static_cast<int>(i);
  }

  // On a shared machine, fork-join over busy cores costs more than it gains (a descheduled
  // thread stalls every chunk): unless OMP_DYNAMIC says otherwise, let the OpenMP runtime
  // size each team from the free cores (libgomp: online CPUs minus the load average).
  if (!std::getenv("OMP_DYNAMIC")) omp_set_dynamic(1);

  try {
    // Pass 1: read, check, spool.
    Spool spool_in(spool_memory());
    const std::size_t chunk = chunk_rows();
    Chunk ch;
    ch.text.resize(chunk);
    ch.line.resize(chunk);
    ch.problem.resize(chunk);
    ch.inputs.resize(chunk * np);
    std::size_t rows_before = 0, line_no = 1;
    for (bool more = true; more;) {
      ch.rows = 0;
      std::size_t chunk_bytes = 0;
      try {
        while (ch.rows < chunk && chunk_bytes < kMaxChunkTextBytes && (more = reader.next(ch.text[ch.rows]))) {
          ++line_no;
          if (ch.text[ch.rows].find_first_not_of(" \t\r") == std::string::npos) continue;  // blank line
          chunk_bytes += ch.text[ch.rows].size();
          ch.line[ch.rows++] = line_no;
        }
      } catch (const LineTooLong& e) {
        return too_long(e);
      }
      const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(ch.rows);
#pragma omp parallel for schedule(dynamic, 256)
      for (std::ptrdiff_t r = 0; r < m; ++r) {
        std::string& text = ch.text[r];
        std::string& problem = ch.problem[r];
        problem.clear();
        const auto cells = split_csv_line(text, ncol + 1);
        auto where = [&] {
          return "row " + std::to_string(rows_before + r + 1) + " (line " + std::to_string(ch.line[r]) + ")";
        };
        if (cells.size() != ncol) {
          problem = where() + ": " + (cells.size() > ncol ? "more than " + std::to_string(ncol) : std::to_string(cells.size())) +
                    " cells, the header has " + std::to_string(ncol);
          continue;
        }
        double* v = ch.inputs.data() + r * np;
        for (std::size_t i = 0; i < np && problem.empty(); ++i) {
          const Parameter& p = q->parameters[i];
          if (column_of[i] == kAbsent) {
            v[i] = *p.fallback;
            continue;
          }
          const std::string& cell = cells[column_of[i]];
          std::string number_problem;
          const auto value = parse_number(cell, &number_problem);
          const std::string why = value ? domain_problem(p, *value) : number_problem;
          if (!why.empty())
            problem = where() + ", column '" + p.name + "': value '" + escape_control(cell.substr(0, 200)) + "' " + why +
                      " " + p.domain;
          else
            v[i] = *value;
        }
        if (!problem.empty()) continue;
        // The input columns as printed: parameters in shortest round-trip form, others as given.
        text.clear();
        for (std::size_t c = 0; c < ncol; ++c) {
          if (c) text += ',';
          if (param_of_column[c] >= 0)
            append_number(text, v[param_of_column[c]]);
          else
            text += cells[c];
        }
      }
      for (std::size_t r = 0; r < ch.rows; ++r)
        if (!ch.problem[r].empty()) {
          err << what << ": " << ch.problem[r] << "\n";
          return 2;
        }
      for (std::size_t r = 0; r < ch.rows; ++r) {
        spool_in.write_value<std::uint64_t>(ch.line[r]);
        spool_in.write(ch.inputs.data() + r * np, np * sizeof(double));
        spool_in.write_value<std::uint64_t>(ch.text[r].size());
        spool_in.write(ch.text[r].data(), ch.text[r].size());
      }
      rows_before += ch.rows;
    }
    const std::size_t total_rows = rows_before;

    // Pass 2: compute in parallel, spool the output in order.
    std::unique_ptr<lookup::TableSet> tables;
    EvalContext ctx;
    Spool spool_out(spool_memory());
    {
      std::string head = list(header);
      for (const auto& name : q->outputs) head += "," + name;
      head += "\n";
      spool_out.write(head.data(), head.size());
    }
    spool_in.rewind();
    const std::size_t nout = q->outputs.size();
    for (std::size_t done = 0; done < total_rows; done += ch.rows) {
      ch.rows = std::min(chunk, total_rows - done);
      for (std::size_t r = 0; r < ch.rows; ++r) {
        ch.line[r] = spool_in.read_value<std::uint64_t>();
        spool_in.read(ch.inputs.data() + r * np, np * sizeof(double));
        ch.text[r].resize(spool_in.read_value<std::uint64_t>());
        spool_in.read(ch.text[r].data(), ch.text[r].size());
      }
      if (o.method == "table" && !tables) {
        try {
          tables = std::make_unique<lookup::TableSet>(o.tables_dir);
        } catch (const std::exception& e) {
          err << what << " --method " << o.method << ": row 1 (line " << ch.line[0] << "): " << e.what() << "\n";
          return 2;
        }
        if (!o.dataset.empty()) tables->substitute(o.dataset);
        ctx.tables = tables.get();
      }
      const std::ptrdiff_t m = static_cast<std::ptrdiff_t>(ch.rows);
#pragma omp parallel
      {
        std::vector<double> result(nout);
#pragma omp for schedule(dynamic, 64)
        for (std::ptrdiff_t r = 0; r < m; ++r) {
          ch.problem[r].clear();
          try {
            method(std::span<const double>(ch.inputs.data() + r * np, np), result, ctx);
          } catch (const std::exception& e) {
            ch.problem[r] = e.what();
            if (ch.problem[r].empty()) ch.problem[r] = "failed";
            continue;
          }
          std::string& text = ch.text[r];
          for (double v : result) {
            text += ',';
            append_number(text, v);
          }
          text += '\n';
        }
      }
      for (std::size_t r = 0; r < ch.rows; ++r) {
        if (!ch.problem[r].empty()) {
          err << what << " --method " << o.method << ": row " << done + r + 1 << " (line " << ch.line[r]
              << "): " << ch.problem[r] << "\n";
          return 2;
        }
        spool_out.write(ch.text[r].data(), ch.text[r].size());
      }
    }
    if (tables && !o.dataset.empty() && !material && !tables->substituted()) {
      const std::string why = tables->refusal();
      if (!why.empty())
        err << what << " --dataset " << escape_control(o.dataset) << ": " << why << "\n";
      else
        err << what << " --dataset " << escape_control(o.dataset) << ": no such dataset in the table file(s) that "
            << q->name << " reads\n";
      return 2;
    }
    spool_out.copy_to(out);
    out.flush();
  } catch (const std::exception& e) {  // temporary-file trouble
    err << what << ": " << e.what() << "\n";
    return 2;
  }
  return 0;
}

}  // namespace brdftab::cli
