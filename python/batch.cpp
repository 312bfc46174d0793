// SPDX-License-Identifier: GPL-3.0-or-later
// Many creep points on several threads: roughroll.solve(..., threads=k). Each point is an
// independent scene_point (its own contact, workspaces and GSL objects: the library keeps no
// global state), so the points can be solved concurrently; each thread takes the next job
// from an atomic counter and writes its own slot, and the results are in the jobs' order
// whatever the schedule: the same numbers as the serial loop. The GIL is released meanwhile,
// except for the calling thread's brief checks for Ctrl-C between points.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <tuple>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "binding.hpp"
#include "roughroll/base/error.hpp"
#include "roughroll/base/text.hpp"

namespace py = pybind11;

namespace roughroll::python {

namespace {

struct job {
    scene s;
    std::optional<load_given> load;
};

// "items[3] (Q = 0.5, scene 'Fig. 2a'): ": which of many items failed, by its index in the
// caller's list (Python's, from 0) and its load, so a batch's error can be traced to its item.
std::string item_name(std::size_t i, const job& j) {
    const auto given = [](const load_given& l) {
        const char* name = l.kind == load_kind::Q ? "Q" : l.kind == load_kind::Q_over_f ? "Q_over_f" : "P1";
        return std::string(name) + " = " + shortest(l.value);
    };
    std::string load = j.load ? given(*j.load) : j.s.Q ? "the scene's Q = " + shortest(*j.s.Q) : "no Q";
    if (!j.s.label.empty()) load += ", scene '" + j.s.label + "'";
    return "items[" + std::to_string(i) + "] (" + load + "): ";
}

// The same error type, its message prefixed with the item: Python then raises the same
// exception class (roughroll_module.cpp) with a message naming the item.
[[noreturn]] void rethrow_naming(const std::exception_ptr& e, const std::string& prefix) {
    try {
        std::rethrow_exception(e);
    } catch (const input_error& x) {
        throw input_error(prefix + x.what());
    } catch (const resolution_error& x) {
        throw resolution_error(prefix + x.what());
    } catch (const numerical_error& x) {
        throw numerical_error(prefix + x.what());
    } catch (const error& x) {
        throw error(prefix + x.what());
    }
    // Anything else (std::bad_alloc) propagates as it is.
}

// The points' JSON in the jobs' order; the first failing job's error (in the jobs' order) is
// rethrown, naming the job, after every thread has finished. The calling thread solves nothing:
// it waits, and every 0.1 s takes the GIL to run Python's signal handlers (they run only there),
// so Ctrl-C stops the batch between points: no thread takes another job, the points being
// solved finish (one point itself is not interruptible), and KeyboardInterrupt is raised.
std::vector<std::string> solve_all(const std::vector<job>& jobs, int threads, const solver_keywords& k) {
    std::vector<std::string> out(jobs.size());
    std::vector<std::exception_ptr> errors(jobs.size());
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    std::mutex m;
    std::condition_variable finished;
    std::size_t running = 0;
    const auto work = [&]() noexcept {
        for (std::size_t i = next++; i < jobs.size() && !stop; i = next++) {
            try {
                out[i] = point_json(jobs[i].s, jobs[i].load, k);
            } catch (...) {
                errors[i] = std::current_exception();
            }
        }
        {
            const std::lock_guard<std::mutex> lock(m);
            --running;
        }
        finished.notify_one();
    };
    std::vector<std::thread> pool;
    const std::size_t wanted = std::min<std::size_t>(static_cast<std::size_t>(threads), jobs.size());
    for (std::size_t t = 0; t < wanted; ++t) {
        try {
            const std::lock_guard<std::mutex> lock(m);
            pool.emplace_back(work);
            ++running;  // under the lock: the thread cannot count itself out before it is in
        } catch (const std::system_error&) {
            break;  // fewer threads than asked for: the rest of the jobs run on those there are
        }
    }
    bool interrupted = false;
    if (pool.empty() && !jobs.empty()) {
        running = 1;
        work();  // no thread at all: this one solves (and cannot watch for Ctrl-C meanwhile)
    }
    {
        std::unique_lock<std::mutex> lock(m);
        while (!finished.wait_for(lock, std::chrono::milliseconds(100), [&] { return running == 0; })) {
            lock.unlock();
            {
                const py::gil_scoped_acquire gil;
                interrupted = PyErr_CheckSignals() != 0;
            }
            lock.lock();
            if (interrupted) {
                stop = true;
                break;
            }
        }
    }
    for (std::thread& t : pool) t.join();
    if (interrupted) {
        const py::gil_scoped_acquire gil;
        throw py::error_already_set();  // KeyboardInterrupt, or whatever the handler raised
    }
    for (std::size_t i = 0; i < jobs.size(); ++i)
        if (errors[i]) rethrow_naming(errors[i], item_name(i, jobs[i]));
    return out;
}

}  // namespace

void bind_batch(py::module_& m) {
    m.def(
        "solve_all",
        // items: (scene, Q, Q_over_f, P1), at most one load given (load_keywords).
        [](const std::vector<std::tuple<scene, std::optional<double>, std::optional<double>, std::optional<double>>>&
               items,
           int threads, std::optional<int> n, std::optional<std::string> method, std::optional<std::string> zones,
           std::optional<double> friction, std::optional<double> tolerance) {
            if (threads < 1 || threads > 1024) throw input_error("threads must lie in [1, 1024]");
            std::vector<job> jobs;
            jobs.reserve(items.size());
            for (const auto& [s, Q, Q_over_f, P1] : items) jobs.push_back({s, load_keywords(Q, Q_over_f, P1)});
            py::gil_scoped_release release;
            return solve_all(jobs, threads, {n, method, zones, friction, tolerance});
        },
        py::arg("items"), py::arg("threads"), py::arg("n"), py::arg("method"), py::arg("zones"), py::arg("friction"),
        py::arg("tolerance") = py::none());
}

}  // namespace roughroll::python
