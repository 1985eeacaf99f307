#include "generators/row_runner.hpp"

#include <fcntl.h>
#include <omp.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "generators/checkpoint.hpp"
#include "generators/manifest.hpp"
#include "lookup/number_format.hpp"

namespace brdftab::gen {

void RowJobs::finish() {
  if (lasts.size() != 1 && lasts.size() != count)
    throw std::logic_error("RowJobs '" + dataset + "' " + stage + ": " + std::to_string(lasts.size()) +
                           " last-axis lists for " + std::to_string(count) + " rows");
  if (outer.size() != count * outer_rank())
    throw std::logic_error("RowJobs '" + dataset + "' " + stage + ": outer coordinates do not match the row count");
  offset.assign(count + 1, 0);
  for (std::size_t i = 0; i < count; ++i) offset[i + 1] = offset[i] + last_of(i).size();
}

std::string row_label(const RowJobs& jobs, std::size_t i) {
  std::string s = "table '" + jobs.dataset + "' " + jobs.stage + " row " + std::to_string(i);
  if (jobs.outer_rank() > 0 && i < jobs.count) {
    const auto o = jobs.outer_of(i);
    s += " (";
    for (std::size_t d = 0; d < o.size(); ++d)
      s += (d ? ", " : "") + jobs.outer_names[d] + " = " + lookup::format_number(o[d]);
    s += ")";
  }
  return s;
}

namespace {

struct TestHooks {
  std::string fail_dataset, fail_stage;
  std::size_t fail_index = 0;
  bool fail = false, fail_abort = false;
  int log_fd = -1;
  int sleep_ms = 0;
  TestHooks() {
    if (const char* f = std::getenv("BRDFTAB_TEST_FAIL_ROW"); f && *f) {
      // <dataset>:<stage>:<index>[:abort]
      std::string s = f;
      const auto a = s.find(':'), b = s.find(':', a + 1);
      if (a != std::string::npos && b != std::string::npos) {
        fail_dataset = s.substr(0, a);
        fail_stage = s.substr(a + 1, b - a - 1);
        const auto c = s.find(':', b + 1);
        fail_index = std::stoul(s.substr(b + 1, c == std::string::npos ? std::string::npos : c - b - 1));
        fail_abort = c != std::string::npos && s.substr(c + 1) == "abort";
        fail = true;
      }
    }
    if (const char* l = std::getenv("BRDFTAB_TEST_ROW_LOG"); l && *l)
      log_fd = ::open(l, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (const char* ms = std::getenv("BRDFTAB_TEST_ROW_SLEEP_MS"); ms && *ms) sleep_ms = std::atoi(ms);
  }
};

const TestHooks& hooks() {
  static const TestHooks h;
  return h;
}

}  // namespace

void run_row(const RowJobs& jobs, std::size_t i, const RowFunction& row, std::span<double> out) {
  const TestHooks& h = hooks();
  if (h.fail && i == h.fail_index && jobs.stage == h.fail_stage && jobs.dataset == h.fail_dataset) {
    if (h.fail_abort) std::abort();
    throw std::runtime_error("injected test failure (BRDFTAB_TEST_FAIL_ROW)");
  }
  if (h.sleep_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(h.sleep_ms));
  row(jobs.outer_of(i), jobs.last_of(i), out.subspan(jobs.offset[i], jobs.offset[i + 1] - jobs.offset[i]));
  if (h.log_fd >= 0) {
    const std::string line = jobs.dataset + " " + jobs.stage + " " + std::to_string(i) + "\n";
    [[maybe_unused]] const ssize_t w = ::write(h.log_fd, line.data(), line.size());  // O_APPEND: one line, whole
  }
}

std::vector<std::size_t> rows_to_compute(const RowJobs& jobs, Checkpoint* checkpoint, std::span<double> out) {
  std::vector<std::size_t> todo;
  todo.reserve(jobs.count);
  for (std::size_t i = 0; i < jobs.count; ++i) {
    const std::vector<double>* v = checkpoint ? checkpoint->find(jobs, i) : nullptr;
    if (v && v->size() == jobs.offset[i + 1] - jobs.offset[i])
      std::copy(v->begin(), v->end(), out.begin() + static_cast<std::ptrdiff_t>(jobs.offset[i]));
    else
      todo.push_back(i);
  }
  return todo;
}

namespace {

// Runs rows `todo` of jobs over OpenMP threads (dynamic, one row per task); after each,
// done(i). Rethrows the first failure, naming its row.
template <class Done>
void local_rows(const RowJobs& jobs, const std::vector<std::size_t>& todo, const RowFunction& row, std::span<double> out,
                const GenerateContext& ctx, bool name_row, Done done) {
  std::exception_ptr error;
  std::string error_row;
  std::mutex error_mutex;
  std::atomic<std::size_t> finished{0};
  const std::string stage = jobs.dataset + ": " + jobs.stage;
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t k = 0; k < todo.size(); ++k) {
    {
      std::lock_guard lock(error_mutex);
      if (error) continue;
    }
    try {
      run_row(jobs, todo[k], row, out);
      done(todo[k]);
      const std::size_t d = ++finished;
      if (omp_get_thread_num() == 0) ctx.report(stage, static_cast<double>(d) / static_cast<double>(todo.size()));
    } catch (...) {
      std::lock_guard lock(error_mutex);
      if (!error) error = std::current_exception(), error_row = row_label(jobs, todo[k]);
    }
  }
  if (error) {
    try {
      std::rethrow_exception(error);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const ManifestError&) {
      throw;
    } catch (const std::exception& e) {
      if (!name_row) throw;
      throw std::runtime_error(error_row + ": " + e.what());
    }
  }
  ctx.report(stage, 1.0);
}

}  // namespace

void compute_rows(const RowJobs& jobs, const RowFunction& row, std::span<double> out, const GenerateContext& ctx) {
  if (out.size() != jobs.values()) throw std::logic_error("compute_rows: output size does not match the row requests");
  if (ctx.rows) return ctx.rows->run(jobs, row, out, ctx);
  std::vector<std::size_t> all(jobs.count);
  for (std::size_t i = 0; i < jobs.count; ++i) all[i] = i;
  local_rows(jobs, all, row, out, ctx, false, [](std::size_t) {});
}

void LocalRowRunner::run(const RowJobs& jobs, const RowFunction& row, std::span<double> out, const GenerateContext& ctx) {
  const std::vector<std::size_t> todo = rows_to_compute(jobs, checkpoint_, out);
  rows_resumed += jobs.count - todo.size();
  rows_computed += todo.size();
  local_rows(jobs, todo, row, out, ctx, true, [&](std::size_t i) {
    if (checkpoint_)
      checkpoint_->append(jobs, i, std::span<const double>(out.data() + jobs.offset[i], jobs.offset[i + 1] - jobs.offset[i]));
  });
  if (checkpoint_) checkpoint_->sync();
}

}  // namespace brdftab::gen
