// Walker's alias method for sampling a discrete distribution in constant time (Walker 1977,
// "An efficient method for generating discrete random variables with general distributions",
// ACM TOMS 3(3); the linear-time construction of Vose 1991, "A linear algorithm for generating
// random numbers with a given distribution", IEEE TSE 17(9)). Cell i keeps a threshold q_i and
// an alias a_i: u in [0, 1) picks slot i = floor(u n) and, with f = u n - i, gives i when
// f < q_i and a_i otherwise. One table entry is read per sample, where inverting a cumulative
// distribution reads log2(n) of them: for a large table that is out of cache (an environment
// map's rows), one memory access instead of ten.
//
// The leftover of u is rescaled to [0, 1) within the chosen slot's share (f / q_i or
// (f - q_i) / (1 - q_i)), uniform given the cell, so it can place the point inside the cell
// as PiecewiseConstant1D's does. Unlike inversion, the map from u to the cell is not monotone,
// so it does not preserve stratification of u. Cells of zero weight are never chosen.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace scatterlab {

class AliasTable {
 public:
  AliasTable() = default;
  // Weights must be finite and >= 0; all zero gives an empty table (total() == 0).
  explicit AliasTable(std::span<const double> weights) { build(weights, slots_); }

  size_t size() const { return slots_.size(); }
  double total() const { return total_; }
  double probability(size_t i) const { return probabilities_[i]; }

  struct Slot {
    float threshold;  // q_i: the share of slot i that stays with cell i
    uint32_t alias;   // a_i
  };

  struct Sample {
    size_t cell;
    double remapped;  // in [0, 1)
  };
  // u in [0, 1); needs total() > 0.
  Sample sample(double u) const { return sampleSlots(slots_.data(), slots_.size(), u); }

  // The same over a table built by `build` into caller-owned storage (so that many tables can
  // share one contiguous array).
  static Sample sampleSlots(const Slot* slots, size_t n, double u) {
    const double scaled = u * double(n);
    const size_t i = std::min(size_t(scaled), n - 1);
    const double f = scaled - double(i);
    const Slot& slot = slots[i];
    if (f < double(slot.threshold)) return {i, std::min(f / double(slot.threshold), OneMinusEpsilon)};
    return {slot.alias,
            std::min((f - double(slot.threshold)) / (1.0 - double(slot.threshold)), OneMinusEpsilon)};
  }

  // Vose's construction into `slots` (resized to weights.size()); returns the total weight.
  // Throws std::invalid_argument for a negative or non-finite weight.
  double build(std::span<const double> weights, std::vector<Slot>& slots) {
    const size_t n = weights.size();
    slots.assign(n, Slot{1.0f, 0});
    probabilities_.assign(n, 0.0);
    total_ = 0.0;
    for (const double w : weights) {
      if (!(w >= 0) || !std::isfinite(w))
        throw std::invalid_argument("AliasTable: weights must be finite and non-negative");
      total_ += w;
    }
    if (!(total_ > 0)) return total_;
    std::vector<double> scaled(n);
    std::vector<uint32_t> small, large;
    for (size_t i = 0; i < n; ++i) {
      probabilities_[i] = weights[i] / total_;
      scaled[i] = probabilities_[i] * double(n);
      (scaled[i] < 1.0 ? small : large).push_back(uint32_t(i));
    }
    while (!small.empty() && !large.empty()) {
      const uint32_t s = small.back(), l = large.back();
      small.pop_back();
      slots[s] = {float(scaled[s]), l};
      scaled[l] -= 1.0 - scaled[s];
      if (scaled[l] < 1.0) {
        large.pop_back();
        small.push_back(l);
      }
    }
    // What is left is 1 up to round-off: those slots keep all of their share.
    for (const uint32_t i : small) slots[i] = {1.0f, i};
    for (const uint32_t i : large) slots[i] = {1.0f, i};
    // A zero-weight cell must never be chosen: its slot goes entirely to its alias, which
    // (should round-off have left the slot its own alias) is then any cell of positive weight.
    const uint32_t positive = uint32_t(
        std::find_if(weights.begin(), weights.end(), [](double w) { return w > 0; }) - weights.begin());
    for (size_t i = 0; i < n; ++i)
      if (weights[i] == 0) {
        slots[i].threshold = 0.0f;
        if (weights[slots[i].alias] == 0) slots[i].alias = positive;
      }
    return total_;
  }

 private:
  static constexpr double OneMinusEpsilon = 0x1.fffffffffffffp-1;

  std::vector<Slot> slots_;
  std::vector<double> probabilities_;
  double total_ = 0.0;
};

}  // namespace scatterlab
