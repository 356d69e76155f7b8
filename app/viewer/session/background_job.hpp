#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>
#include "nome/stop_token.hpp"

#include "nome/thread_support.hpp"

namespace nome::viewer {

// Runs the latest request off the UI thread (live editing: a slider moved again supersedes the work in
// flight). submit() asks the running job to stop, without waiting for it, and starts the new one; take()
// hands over the result of the latest request only, so stale geometry never reaches the screen. A job
// polls its stop_token between stages to give up early. Where threads cannot start (can_start_threads),
// take() runs the latest request on the UI thread: the viewer shows the same, only not concurrently, and
// a request superseded before the next frame costs nothing.
template <typename Result>
class BackgroundJob {
 public:
  using Work = std::function<Result(nome::stop_token)>;

  BackgroundJob() = default;
  ~BackgroundJob() { cancel(); }
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;

  void submit(Work work) {
    retire();
    auto state = std::make_shared<State>();
    state_ = state;
    started_ = std::chrono::steady_clock::now();
    if (!can_start_threads()) {
      pending_ = std::move(work);
      return;
    }
    thread_ = nome::jthread(
        [state, work = std::move(work)](nome::stop_token stop) { run(work, std::move(stop), *state); });
  }

  // Waits up to `patience` for the latest job; returns its result once (rethrows its exception).
  std::optional<Result> take(std::chrono::milliseconds patience = std::chrono::milliseconds(0)) {
    reap();
    if (!state_) return std::nullopt;
    if (pending_) run(std::exchange(pending_, nullptr), {}, *state_);
    std::unique_lock lock(state_->mutex);
    if (!state_->done.wait_for(lock, patience, [&] { return state_->is_done; })) return std::nullopt;
    auto state = std::move(state_);
    lock.unlock();
    if (thread_.joinable()) thread_.join();
    if (state->error) std::rethrow_exception(state->error);
    return std::move(state->result);
  }

  bool is_busy() const { return state_ != nullptr; }
  double seconds_running() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  }

  // Stops every job (results dropped) and waits for their threads.
  void cancel() {
    retire();
    for (auto& old : retired_) old.thread.join();
    retired_.clear();
  }

 private:
  struct State {
    std::mutex mutex;
    std::condition_variable done;
    bool is_done = false;
    std::optional<Result> result;
    std::exception_ptr error;
  };
  struct Retired {
    std::shared_ptr<State> state;
    nome::jthread thread;
  };

  static void run(const Work& work, nome::stop_token stop, State& state) {
    std::optional<Result> result;
    std::exception_ptr error;
    try {
      result.emplace(work(std::move(stop)));
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard lock(state.mutex);
    state.result = std::move(result);
    state.error = error;
    state.is_done = true;
    state.done.notify_all();
  }

  // The job in flight is told to stop and set aside; its thread is joined once it has finished.
  void retire() {
    if (thread_.joinable()) {
      thread_.request_stop();
      retired_.push_back({std::move(state_), std::move(thread_)});
    }
    state_.reset();
    pending_ = nullptr;
    reap();
  }
  void reap() {
    for (auto it = retired_.begin(); it != retired_.end();) {
      bool is_done = false;
      {
        std::lock_guard lock(it->state->mutex);
        is_done = it->state->is_done;
      }
      if (is_done) {
        it->thread.join();
        it = retired_.erase(it);
      } else {
        ++it;
      }
    }
  }

  std::shared_ptr<State> state_;
  nome::jthread thread_;
  Work pending_;  // the latest request, where no thread can start: take() runs it
  std::vector<Retired> retired_;
  std::chrono::steady_clock::time_point started_{};
};

}  // namespace nome::viewer
