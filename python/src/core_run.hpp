#pragma once
// Shared machinery of the `brdftab._core` extension: the errors policy, interruptible runs
// (Ctrl-C within 0.1 s with the GIL released), and column checks.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace brdftab::pycore {

namespace py = pybind11;

// What to do with an input outside the domain: raise ValueError naming the parameter, value
// and domain; give NaN for that element; or clamp it to the nearest edge.
enum class Errors { raise, nan, clamp };

inline Errors parse_errors(const std::string& s) {
  if (s == "raise") return Errors::raise;
  if (s == "nan") return Errors::nan;
  if (s == "clamp") return Errors::clamp;
  throw py::value_error("errors = '" + s + "' is not one of 'raise', 'nan', 'clamp'");
}

// How often a waiting call looks for Ctrl-C (PyErr_CheckSignals): well inside the 0.1 s promise.
inline constexpr std::chrono::milliseconds kSignalPoll{20};

// Runs work(cancel) on a worker thread while this thread waits without the GIL, looking for
// signals every kSignalPoll. work returns "" or an error message (raised as ValueError).
// On KeyboardInterrupt (or any pending Python exception from a signal handler) `cancel` is set
// and the worker is detached: the caller gets the exception at once, and the worker stops
// after its current element. work must therefore own everything it touches (no Python
// objects, no references into the caller's frame).
inline void run_interruptible(std::function<std::string(const std::atomic<bool>& cancel)> work) {
  struct Shared {
    std::mutex m;
    std::condition_variable cv;
    bool done = false;
    std::string error;
    std::atomic<bool> cancel{false};
  };
  auto s = std::make_shared<Shared>();
  std::thread t([s, work = std::move(work)] {
    std::string e;
    try {
      e = work(s->cancel);
    } catch (const std::exception& x) {
      e = x.what();
    } catch (...) {
      e = "unknown error";
    }
    {
      std::lock_guard lock(s->m);
      s->error = std::move(e);
      s->done = true;
    }
    s->cv.notify_all();
  });
  for (;;) {
    bool done = false;
    {
      py::gil_scoped_release release;
      std::unique_lock lock(s->m);
      done = s->cv.wait_for(lock, kSignalPoll, [&] { return s->done; });
    }
    if (done) break;
    if (PyErr_CheckSignals() != 0) {
      s->cancel = true;
      t.detach();
      throw py::error_already_set();
    }
  }
  t.join();
  if (!s->error.empty()) throw py::value_error(s->error);
}

// Checks for Ctrl-C between chunks of a loop that holds the GIL between them.
inline void check_signals() {
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

using Column = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The columns must be 1-D, of one length; returns it.
inline std::size_t common_length(const std::vector<Column>& cols, const std::string& who) {
  std::size_t n = cols.empty() ? 0 : static_cast<std::size_t>(cols[0].size());
  for (const auto& c : cols) {
    if (c.ndim() != 1) throw py::value_error(who + ": columns must be 1-D (the Python layer flattens them)");
    if (static_cast<std::size_t>(c.size()) != n) throw py::value_error(who + ": columns differ in length");
  }
  return n;
}

}  // namespace brdftab::pycore
