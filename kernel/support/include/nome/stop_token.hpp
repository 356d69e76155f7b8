#pragma once

#include <atomic>
#include <memory>
#include <thread>
#include <type_traits>
#include <utility>
#include <version>
#if defined(__cpp_lib_jthread)
#include <stop_token>
#endif

// std::jthread and std::stop_token where the standard library has them; the same interface (the part Nome
// uses) where it does not, as in the browser build's libc++. The portable ones are compiled everywhere so
// that they are tested beside the standard ones.
namespace nome {
namespace portable {

class stop_token {
 public:
  stop_token() noexcept = default;
  bool stop_requested() const noexcept { return state_ && state_->load(std::memory_order_acquire); }
  bool stop_possible() const noexcept { return state_ != nullptr; }

 private:
  friend class stop_source;
  explicit stop_token(std::shared_ptr<std::atomic<bool>> state) noexcept : state_(std::move(state)) {}
  std::shared_ptr<std::atomic<bool>> state_;
};

class stop_source {
 public:
  stop_source() : state_(std::make_shared<std::atomic<bool>>(false)) {}
  // True for the call that made the request.
  bool request_stop() noexcept { return state_ && !state_->exchange(true, std::memory_order_acq_rel); }
  bool stop_requested() const noexcept { return state_ && state_->load(std::memory_order_acquire); }
  stop_token get_token() const noexcept { return stop_token(state_); }

 private:
  std::shared_ptr<std::atomic<bool>> state_;
};

// A thread that asks its work to stop and joins when it goes away; the work takes a stop_token first when
// it accepts one.
class jthread {
 public:
  jthread() noexcept = default;
  template <typename F, typename... Args>
  requires(!std::is_same_v<std::remove_cvref_t<F>, jthread>) explicit jthread(F&& f, Args&&... args) {
    if constexpr (std::is_invocable_v<std::decay_t<F>, stop_token, std::decay_t<Args>...>)
      thread_ = std::thread(std::forward<F>(f), source_.get_token(), std::forward<Args>(args)...);
    else
      thread_ = std::thread(std::forward<F>(f), std::forward<Args>(args)...);
  }
  ~jthread() { stop_and_join(); }
  jthread(const jthread&) = delete;
  jthread& operator=(const jthread&) = delete;
  jthread(jthread&&) noexcept = default;
  jthread& operator=(jthread&& other) noexcept {
    if (this != &other) {
      stop_and_join();
      source_ = std::move(other.source_);
      thread_ = std::move(other.thread_);
    }
    return *this;
  }

  bool joinable() const noexcept { return thread_.joinable(); }
  void join() { thread_.join(); }
  void detach() { thread_.detach(); }
  bool request_stop() noexcept { return source_.request_stop(); }

 private:
  void stop_and_join() {
    if (!thread_.joinable()) return;
    source_.request_stop();
    thread_.join();
  }

  stop_source source_;
  std::thread thread_;
};

}  // namespace portable

#if defined(__cpp_lib_jthread)
using std::jthread;
using std::stop_source;
using std::stop_token;
#else
using portable::jthread;
using portable::stop_source;
using portable::stop_token;
#endif

}  // namespace nome
