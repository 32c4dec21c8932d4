// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A piece of work that runs on a thread of its own, but only while its caller waits: the caller
// gives it a turn (`give_turn()`), and the work runs until it asks the caller for something
// (`ask()`) or ends.  What it asks for runs on the caller's thread, when the caller chooses
// (`serve()`): a distributed field exchanges only on the thread that updated it, and only
// between the exchanges of the caller's own work.  The two never run at the same time, so the
// work may share the caller's data (each turn's hand-over orders their accesses), and a run is
// as deterministic as one that does the work and the caller's one after the other.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_TAKING_TURNS_H
#define CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_TAKING_TURNS_H

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace internal {

class Taking_turns {
public:
  /// What the work waits for: `LOCAL` may be served at any time, `EXCHANGE` only where the
  /// caller is between exchanges of its own.
  enum class Request { NONE, LOCAL, EXCHANGE };

  /// Starts `work` on its thread; it runs at the first `give_turn()`.
  explicit Taking_turns(std::function<void(Taking_turns&)> work)
      : m_thread([this, work = std::move(work)] { run(work); })
  {
  }
  Taking_turns(const Taking_turns&) = delete;
  Taking_turns& operator=(const Taking_turns&) = delete;

  /// Ends unfinished work: what it waits for throws in its thread, which then unwinds.
  ~Taking_turns()
  {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_cancelled = true;
      m_work_turn = true;
    }
    m_changed.notify_all();
    m_thread.join();
  }

  // The caller's side.

  /// Whether the work has ended (`rethrow_failure()` tells whether it failed).
  bool finished() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_finished;
  }

  /// What the work waits for.
  Request pending() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_pending;
  }

  /// Runs what the work asked for, here.  Requires `pending() != NONE`.
  void serve()
  {
    std::function<void()> request;
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      request = std::move(m_request);
      m_pending = Request::NONE;
    }
    try {
      request();
    } catch (...) {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_served_failure = std::current_exception();
    }
  }

  /// Lets the work run until it asks for something or ends; nothing when it waits for a request
  /// not served yet, or has ended.
  void give_turn()
  {
    std::unique_lock<std::mutex> lock(m_mutex);
    if (m_finished || m_pending != Request::NONE)
      return;
    m_work_turn = true;
    m_changed.notify_all();
    m_changed.wait(lock, [this] { return !m_work_turn; });
  }

  /// Serves the work's requests and gives it turns until it ends.
  void finish()
  {
    while (!finished()) {
      if (pending() != Request::NONE)
        serve();
      give_turn();
    }
  }

  /// Throws what the work threw, if it did.
  void rethrow_failure() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_failure)
      std::rethrow_exception(m_failure);
  }

  // The work's side.

  /// Runs `f()` on the caller's thread, when the caller serves it, and returns its result (or
  /// throws what it threw); the work's turn ends here.
  template <class F>
  auto ask(Request kind, F f) -> decltype(f())
  {
    using Result = decltype(f());
    std::optional<std::conditional_t<std::is_void_v<Result>, bool, Result>> result;
    {
      std::unique_lock<std::mutex> lock(m_mutex);
      m_request = [&] {
        if constexpr (std::is_void_v<Result>) {
          f();
          result.emplace(true);
        }
        else
          result.emplace(f());
      };
      m_pending = kind;
      m_work_turn = false;
      m_changed.notify_all();
      m_changed.wait(lock, [this] { return m_work_turn; });
      if (m_cancelled)
        throw Cancelled();
      if (m_served_failure)
        std::rethrow_exception(std::exchange(m_served_failure, nullptr));
    }
    if constexpr (!std::is_void_v<Result>)
      return std::move(*result);
  }

private:
  struct Cancelled {};

  void run(const std::function<void(Taking_turns&)>& work)
  {
    {
      std::unique_lock<std::mutex> lock(m_mutex);
      m_changed.wait(lock, [this] { return m_work_turn; });
    }
    std::exception_ptr failure;
    if (!cancelled()) {
      try {
        work(*this);
      } catch (const Cancelled&) {
      } catch (...) {
        failure = std::current_exception();
      }
    }
    std::lock_guard<std::mutex> lock(m_mutex);
    m_failure = failure;
    m_finished = true;
    m_pending = Request::NONE;
    m_work_turn = false;
    m_changed.notify_all();
  }

  bool cancelled() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_cancelled;
  }

  mutable std::mutex m_mutex;
  std::condition_variable m_changed;
  bool m_work_turn = false, m_finished = false, m_cancelled = false;
  Request m_pending = Request::NONE;
  std::function<void()> m_request;
  std::exception_ptr m_failure, m_served_failure;
  std::thread m_thread; // last: starts once the members above are made
};

} // namespace internal
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_INTERNAL_TAKING_TURNS_H
