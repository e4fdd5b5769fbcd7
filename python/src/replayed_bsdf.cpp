#include "python/src/replayed_bsdf.h"

#include <bit>

namespace scatterlab::python {
namespace {

enum QueryKind : uint64_t { EvalQuery = 1, PdfQuery = 2, SampleQuery = 3 };

// MurmurHash3's 64-bit finaliser: a bijection that mixes every input bit into every output bit.
uint64_t mix64(uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  h *= 0xc4ceb93fe53b9a87ULL;
  h ^= h >> 33;
  return h;
}

Query query(const Vec3d& a, const Vec3d& b) { return {a.x, a.y, a.z, b.x, b.y, b.z}; }
Query query(const Vec3d& wi, double uLobe, const Vec2d& u) { return {wi.x, wi.y, wi.z, uLobe, u.x, u.y}; }

size_t totalSize(const std::vector<const std::vector<Miss>*>& lists) {
  size_t total = 0;
  for (const std::vector<Miss>* list : lists) total += list->size();
  return total;
}

void addNonEmpty(const std::vector<Miss>& list, std::vector<const std::vector<Miss>*>& to) {
  if (!list.empty()) to.push_back(&list);
}

}  // namespace

template <typename Value> Value ReplayedBsdf::lookUp(const QueryTable<Value>& table, const Query& q,
                                                     uint64_t kind, std::vector<Miss>& misses,
                                                     const Value& unknown) const {
  const QueryKey key = queryKey(q, kind);
  if (const Value* value = table.find(key)) return *value;
  misses.push_back({key, q});
  if (!missed_.load(std::memory_order_relaxed)) missed_.store(true, std::memory_order_relaxed);
  return unknown;
}

QueryKey queryKey(const Query& query, uint64_t kind) {
  // Two lanes with different odd multipliers and rotations (xxHash's round), each finalised by
  // mix64: independent 64-bit hashes of the same bits.
  uint64_t a = kind * 0x9e3779b97f4a7c15ULL, b = kind * 0xc2b2ae3d27d4eb4fULL + 0x165667b19e3779f9ULL;
  for (const double value : query) {
    const uint64_t word = std::bit_cast<uint64_t>(value);
    a = std::rotl(a ^ (word * 0x87c37b91114253d5ULL), 31) * 0x9e3779b97f4a7c15ULL;
    b = std::rotl(b + (word * 0x4cf5ad432745937fULL), 27) * 0xc2b2ae3d27d4eb4fULL;
  }
  QueryKey key{mix64(a), mix64(b ^ 0x27d4eb2f165667c5ULL)};
  if (key == QueryKey{}) key.b = 1;  // {0, 0} marks an empty slot
  return key;
}

// The kit asks for eval and pdf at the same directions, one after the other, and asks for the
// second only when the first says the direction matters (consistency.h): a miss of one records
// the other too, so that both arrive in the same round rather than one round apart.
Rgb ReplayedBsdf::eval(const Vec3d& wi, const Vec3d& wo, TransportMode) const {
  const Query q = query(wi, wo);
  MissBuffer& misses = misses_.local();
  const size_t before = misses.evals.size();
  const Rgb f = lookUp(evals_, q, EvalQuery, misses.evals, Rgb(0.0));
  if (misses.evals.size() != before) lookUp(pdfs_, q, PdfQuery, misses.pdfs, 0.0);
  return f;
}

double ReplayedBsdf::pdf(const Vec3d& wi, const Vec3d& wo, TransportMode) const {
  const Query q = query(wi, wo);
  MissBuffer& misses = misses_.local();
  const size_t before = misses.pdfs.size();
  const double p = lookUp(pdfs_, q, PdfQuery, misses.pdfs, 0.0);
  if (misses.pdfs.size() != before) lookUp(evals_, q, EvalQuery, misses.evals, Rgb(0.0));
  return p;
}

std::optional<BsdfSample> ReplayedBsdf::sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                               TransportMode) const {
  return lookUp(samples_, query(wi, uLobe, u), SampleQuery, misses_.local().samples,
                std::optional<BsdfSample>());
}

void ReplayedBsdf::evalAndPdf(std::span<const Vec3d> wi, std::span<const Vec3d> wo, TransportMode,
                              std::span<Rgb> f, std::span<double> pdf) const {
  if (missed()) {
    std::fill(f.begin(), f.end(), Rgb(0.0));
    std::fill(pdf.begin(), pdf.end(), 0.0);
    return;
  }
  bulk_(wi, wo, f, pdf);
}

size_t ReplayedBsdf::Misses::size() const { return totalSize(evals) + totalSize(pdfs) + totalSize(samples); }

ReplayedBsdf::Misses ReplayedBsdf::takeMisses() {
  Misses all;
  for (const MissBuffer& buffer : misses_) {
    addNonEmpty(buffer.evals, all.evals);
    addNonEmpty(buffer.pdfs, all.pdfs);
    addNonEmpty(buffer.samples, all.samples);
  }
  evals_.reserve(totalSize(all.evals));
  pdfs_.reserve(totalSize(all.pdfs));
  samples_.reserve(totalSize(all.samples));
  return all;
}

void ReplayedBsdf::clearMisses() {
  for (MissBuffer& buffer : misses_) {
    buffer.evals.clear();
    buffer.pdfs.clear();
    buffer.samples.clear();
  }
  missed_.store(false, std::memory_order_relaxed);
}

void ReplayedBsdf::forget() {
  evals_.clear();
  pdfs_.clear();
  samples_.clear();
}

}  // namespace scatterlab::python
