#include "nome/mesh/names.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <mutex>
#include <optional>

namespace nome {
namespace {
std::atomic<std::uint64_t> lists_made_count{0};
}  // namespace

// The names: `list` alone, or runs (each a grid rule, a slice of another state's list, or empty names)
// whose whole list is made on the first walk.
struct Names::State {
  struct Run {
    std::size_t count = 0;
    std::string prefix;
    std::optional<Grid> grid;
    std::shared_ptr<const State> slice_of;  // a list-only state: names [first, first + count) of its list
    std::size_t first = 0;
    bool operator==(const Run&) const = default;

    std::string name(std::size_t k) const {
      if (slice_of) return prefix + slice_of->list[first + k];
      if (!grid) return prefix;
      const std::size_t per_cell = grid->suffixes.size();
      const std::size_t cell = k / per_cell;
      char text[48];
      char* end = text;
      *end++ = grid->letter;
      end = std::to_chars(end, text + 24, grid->first_row + cell / grid->columns).ptr;
      *end++ = '_';
      end = std::to_chars(end, text + 48, cell % grid->columns).ptr;
      std::string out;
      out.reserve(prefix.size() + std::size_t(end - text) + grid->suffixes[k % per_cell].size());
      out.append(prefix).append(text, end).append(grid->suffixes[k % per_cell]);
      return out;
    }
  };

  std::vector<std::string> list;
  std::vector<Run> runs;            // empty: the names are `list`
  std::vector<std::size_t> starts;  // where each run begins
  std::size_t run_total = 0;
  mutable std::once_flag made;
  mutable std::vector<std::string> made_list;

  std::size_t size() const { return runs.empty() ? list.size() : run_total; }
  void add_run(Run run) {
    if (run.count == 0) return;
    starts.push_back(run_total);
    run_total += run.count;
    runs.push_back(std::move(run));
  }
  // The runs that read as the names of `state` (a list becomes one slice of it).
  void add_runs_of(const std::shared_ptr<State>& state) {
    if (!state->runs.empty()) {
      for (const Run& r : state->runs) add_run(r);
      return;
    }
    Run slice;
    slice.count = state->list.size();
    slice.slice_of = state;
    add_run(std::move(slice));
  }
  std::string name(std::size_t i) const {
    if (runs.empty()) return list[i];
    const std::size_t r = std::size_t(std::upper_bound(starts.begin(), starts.end(), i) - starts.begin()) - 1;
    return runs[r].name(i - starts[r]);
  }
  const std::vector<std::string>& whole() const {
    if (runs.empty()) return list;
    std::call_once(made, [this] {
      lists_made_count.fetch_add(1, std::memory_order_relaxed);
      made_list.reserve(run_total);
      for (const Run& r : runs)
        for (std::size_t k = 0; k < r.count; ++k) made_list.push_back(r.name(k));
    });
    return made_list;
  }
};

Names::Names(std::vector<std::string> list) {
  if (list.empty()) return;
  state_ = std::make_shared<State>();
  state_->list = std::move(list);
}

Names Names::grid(const Grid& grid, std::size_t count) {
  if (count == 0) return {};
  auto state = std::make_shared<State>();
  Grid g = grid;
  if (g.suffixes.empty()) g.suffixes.emplace_back();
  g.columns = std::max<std::size_t>(g.columns, 1);
  state->add_run({count, "", std::move(g), nullptr, 0});
  return Names(std::move(state));
}

std::size_t Names::size() const {
  return state_ ? state_->size() : 0;
}

std::string Names::operator[](std::size_t i) const {
  return state_->name(i);
}

const std::vector<std::string>& Names::list() const {
  static const std::vector<std::string> none;
  return state_ ? state_->whole() : none;
}

std::vector<std::string>& Names::writable() {
  if (!state_) {
    state_ = std::make_shared<State>();
  } else if (!state_->runs.empty() || state_.use_count() > 1) {
    auto own = std::make_shared<State>();
    own->list = state_->whole();
    state_ = std::move(own);
  }
  return state_->list;
}

void Names::resize(std::size_t n) {
  const std::size_t now = size();
  if (n == now) return;
  if (n < now || !state_ || state_->runs.empty()) {
    writable().resize(n);
    return;
  }
  auto grown = std::make_shared<State>();
  grown->add_runs_of(state_);
  grown->add_run({n - now, "", std::nullopt, nullptr, 0});
  state_ = std::move(grown);
}

void Names::append(const Names& other) {
  if (other.empty()) return;
  if (empty()) {
    *this = other;
    return;
  }
  if (state_->runs.empty() && other.state_->runs.empty()) {
    const Names kept = other;  // shares the list, so appending a list to itself copies it first
    std::vector<std::string>& own = writable();
    own.insert(own.end(), kept.state_->list.begin(), kept.state_->list.end());
    return;
  }
  auto joined = std::make_shared<State>();
  joined->add_runs_of(state_);
  joined->add_runs_of(other.state_);
  state_ = std::move(joined);
}

void Names::add_prefix(const std::string& prefix) {
  if (prefix.empty() || empty()) return;
  if (state_->runs.empty()) {
    for (std::string& n : writable()) n.insert(0, prefix);
    return;
  }
  auto prefixed = std::make_shared<State>();
  for (State::Run r : state_->runs) {
    r.prefix.insert(0, prefix);
    prefixed->add_run(std::move(r));
  }
  state_ = std::move(prefixed);
}

bool Names::operator==(const Names& other) const {
  if (state_ == other.state_) return true;
  if (size() != other.size()) return false;
  if (empty()) return true;
  if (!state_->runs.empty() && state_->runs == other.state_->runs) return true;
  if (state_->runs.empty() && other.state_->runs.empty()) return state_->list == other.state_->list;
  for (std::size_t i = 0; i < size(); ++i)
    if ((*this)[i] != other[i]) return false;
  return true;
}

std::uint64_t Names::lists_made() {
  return lists_made_count.load(std::memory_order_relaxed);
}

}  // namespace nome
