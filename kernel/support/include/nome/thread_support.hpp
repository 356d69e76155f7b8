#pragma once

namespace nome {

// Whether this build can start threads at all: a WebAssembly build without pthreads cannot (pthread_create
// fails, and std::thread's constructor throws, or aborts where exceptions are off).
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
inline constexpr bool build_has_threads = false;
#else
inline constexpr bool build_has_threads = true;
#endif

// Whether work may start threads now. Every place that would start one does that work on the calling
// thread instead when it may not, with the same results bit for bit.
bool can_start_threads() noexcept;

// While one lives, can_start_threads() is false: native tests run what a build without threads runs. Only
// tests make one, while no other thread runs kernel work; a place decides once per piece of work (a pass,
// a file, a job), so a switch in the middle of one changes nothing in it.
class WithoutThreads {
 public:
  WithoutThreads();
  ~WithoutThreads();
  WithoutThreads(const WithoutThreads&) = delete;
  WithoutThreads& operator=(const WithoutThreads&) = delete;

 private:
  bool could_before_;
};

}  // namespace nome
