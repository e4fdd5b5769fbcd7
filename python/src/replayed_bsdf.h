// The test kit on a BSDF written in Python (docs/python.md, "The kit on any object"). The kit
// (validation/bsdf_check.h) calls eval, pdf and sample one direction at a time, from TBB threads,
// and decides what to ask next from what it got (a sample's wo, then eval and pdf there; the
// adaptive quadrature's next points). Calling Python per value would take minutes and hold the
// GIL in every thread. ReplayedBsdf runs the kit unchanged instead, in rounds:
//   1. the kit runs on this model; a value already known comes from a table, an unknown one is
//      recorded and answered with "nothing" (eval 0, pdf 0, sampling failed);
//   2. the recorded queries go to the Python object in a few large batches (PythonBsdf) and
//      their answers enter the tables;
//   3. repeat until a run asks for nothing unknown.
// That last run saw the object's own value at every query, so its report is exactly the kit's
// report on the object; earlier runs are discarded. Each round answers at least the first query
// the true run would make that the tables lacked, so the rounds end; in practice their number is
// the depth of the kit's longest chain of dependent queries that goes through the tables: three
// for one incident angle (samples, then the values at the sampled directions, then a clean run),
// since the quadratures ask the object directly (below); up to about twenty for the negative
// controls, whose broken models wrap this one and integrate through the tables.
//
// Queries are keyed by a 128-bit hash of their arguments' bits (two independent 64-bit lanes;
// a collision among 10^8 queries has probability about 10^-23). A miss carries its key, so a
// key is computed once per query and round.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

#include "materials/bsdf/bsdf.h"
#include "validation/bulk_evaluated_bsdf.h"

namespace scatterlab::python {

// What the Python object declares about itself (its optional attributes, docs/python.md).
struct DeclaredProperties {
  LobeFlags flags = LobeFlags::GlossyReflection;
  bool lossless = false;
  double losslessAccuracy = 0.0;
  bool reciprocal = true;
};

// (wi, wo) of an eval or pdf query, (wi, uLobe, u) of a sample query.
using Query = std::array<double, 6>;

struct QueryKey {
  uint64_t a = 0, b = 0;
  bool operator==(const QueryKey&) const = default;
  bool operator<(const QueryKey& other) const { return a != other.a ? a < other.a : b < other.b; }
};

// A query the tables could not answer, with its key.
struct Miss {
  QueryKey key;
  Query query;
};

// An open-addressing table from query keys to values: lookups from many threads while no insert
// runs (inserts happen between the kit's runs). Each slot holds its key and its value together:
// a table of 10^7 entries lives in DRAM, and a lookup costs about one cache miss, not three.
template <typename Value> class QueryTable {
 public:
  const Value* find(const QueryKey& key) const {
    if (slots_.empty()) return nullptr;
    for (size_t slot = key.a & mask_;; slot = (slot + 1) & mask_) {
      if (slots_[slot].key == key) return &slots_[slot].value;
      if (slots_[slot].key == QueryKey{}) return nullptr;
    }
  }
  // Room for `count` more entries without growing while they are inserted (one rehash).
  void reserve(size_t count) {
    size_t capacity = std::max<size_t>(slots_.size(), 1024);
    while (overfull(size_ + count, capacity)) capacity *= 2;
    if (capacity > slots_.size()) rehash(capacity);
  }
  void insert(const QueryKey& key, const Value& value) {
    if (overfull(size_ + 1, slots_.size())) rehash(slots_.empty() ? 1024 : 2 * slots_.size());
    size_t slot = key.a & mask_;
    while (!(slots_[slot].key == QueryKey{}) && !(slots_[slot].key == key)) slot = (slot + 1) & mask_;
    if (slots_[slot].key == key) return;
    slots_[slot] = {key, value};
    ++size_;
  }
  // Empties the table, keeping its memory for the next part of the check.
  void clear() {
    std::fill(slots_.begin(), slots_.end(), Slot{});
    size_ = 0;
  }
  size_t size() const { return size_; }

 private:
  struct Slot {
    QueryKey key;  // {0, 0}: empty
    Value value{};
  };
  // Linear probing stays short up to three quarters full (Knuth: 2.5 probes per lookup that
  // finds its key, 8.5 per one that does not), and the tables are the replay's largest memory.
  static bool overfull(size_t entries, size_t capacity) { return 4 * entries > 3 * capacity; }

  void rehash(size_t capacity) {
    std::vector<Slot> slots(capacity);
    const size_t mask = slots.size() - 1;
    for (const Slot& old : slots_) {
      if (old.key == QueryKey{}) continue;
      size_t slot = old.key.a & mask;
      while (!(slots[slot].key == QueryKey{})) slot = (slot + 1) & mask;
      slots[slot] = old;
    }
    slots_ = std::move(slots);
    mask_ = mask;
  }

  std::vector<Slot> slots_;
  size_t size_ = 0;
  size_t mask_ = 0;
};

QueryKey queryKey(const Query& query, uint64_t kind);

// The kit's quadratures of pdf and f |cos| (the longest chains of dependent queries) do not go
// through the tables: as a BulkEvaluatedBsdf, the model hands each level of them to the object at
// once (`bulk`, which takes the GIL), in the run itself. A run that has already missed a value
// will be repeated, so its quadratures get zeros instead and cost nothing.
class ReplayedBsdf final : public BsdfModel, public BulkEvaluatedBsdf {
 public:
  using BulkEvaluation = std::function<void(std::span<const Vec3d> wi, std::span<const Vec3d> wo,
                                            std::span<Rgb> f, std::span<double> pdf)>;
  ReplayedBsdf(const DeclaredProperties& declared, BulkEvaluation bulk)
      : declared_(declared), bulk_(std::move(bulk)) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode mode = TransportMode::Radiance) const override;
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode mode = TransportMode::Radiance) const override;
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode mode = TransportMode::Radiance) const override;
  LobeFlags flags() const override { return declared_.flags; }
  bool isLossless() const override { return declared_.lossless; }
  double losslessAccuracy() const override { return declared_.losslessAccuracy; }
  bool isReciprocal() const override { return declared_.reciprocal; }
  void evalAndPdf(std::span<const Vec3d> wi, std::span<const Vec3d> wo, TransportMode mode, std::span<Rgb> f,
                  std::span<double> pdf) const override;

  // The queries the last run could not answer, as each thread recorded them: views of the
  // threads' buffers, valid until clearMisses(). A query two threads missed comes twice and gets
  // the same answer twice: the object is a function of its arguments, so neither the order nor
  // the batches change a value. Makes room in the tables for their answers.
  struct Misses {
    std::vector<const std::vector<Miss>*> evals, pdfs, samples;  // one list per thread
    size_t size() const;
  };
  Misses takeMisses();
  // Empties the threads' buffers, keeping their memory for the next run (a fresh allocation of
  // hundreds of MB costs more in page faults than the run that fills it), and starts a new run.
  void clearMisses();
  // Whether this run has met a value the tables lack.
  bool missed() const { return missed_.load(std::memory_order_relaxed); }

  void answerEval(const Miss& miss, const Rgb& f) { evals_.insert(miss.key, f); }
  void answerPdf(const Miss& miss, double pdf) { pdfs_.insert(miss.key, pdf); }
  void answerSample(const Miss& miss, const std::optional<BsdfSample>& sample) {
    samples_.insert(miss.key, sample);
  }
  // Forgets every answer (between independent parts of a check, so that the tables hold one
  // part's queries at a time).
  void forget();
  size_t answerCount() const { return evals_.size() + pdfs_.size() + samples_.size(); }

 private:
  struct MissBuffer {
    std::vector<Miss> evals, pdfs, samples;
  };

  template <typename Value> Value lookUp(const QueryTable<Value>& table, const Query& q, uint64_t kind,
                                         std::vector<Miss>& misses, const Value& unknown) const;

  DeclaredProperties declared_;
  BulkEvaluation bulk_;
  mutable std::atomic<bool> missed_{false};
  QueryTable<Rgb> evals_;
  QueryTable<double> pdfs_;
  QueryTable<std::optional<BsdfSample>> samples_;
  mutable tbb::enumerable_thread_specific<MissBuffer> misses_;
};

}  // namespace scatterlab::python
