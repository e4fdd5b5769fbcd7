// The film of estimators whose samples add to pixels other than their own: light tracing and
// BDPT. Sample s of pixel p (a "unit", as in the path tracer: its random numbers are
// SampleStream(seed, p, s, part)) gives a camera value for its own pixel and any number of
// splats, film points with a value, which the pixel filter spreads over the pixels around them
// (PixelFilter::density). A pixel's value is
//   (1/spp) sum over its units of the camera value  +  (1/N) sum over all N units of the splats,
// N = width x height x spp: every unit starts one light path, and the splats estimate each
// pixel's share of the light those paths carry (Veach 1997, sec. 10.3.4).
//
// Variance layer: the units are independent, so the variance of a pixel's value is the camera
// values' s^2 / spp plus, for the splats, (sum Y^2 - (sum Y)^2 / N) / (N (N - 1)) with Y a
// unit's total splat to the pixel (a unit's splats to one pixel are added before squaring).
//
// Same bits for any thread count: the units are cut into chunks (a 16 x 16 tile of pixels times
// a slice of 8 samples), each chunk records its camera values and splats in order, and the
// chunks are added to the film one after another in a fixed order, in batches whose chunks run
// in parallel. A unit dropped by the film's rule (sample_value.h: a walk that ended on an invalid
// weight, or a camera value, albedo or splat that is not finite or has a negative channel; never
// expected) contributes nothing and is counted by kind (RenderStatistics).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "integrator/render.h"
#include "integrator/sample_value.h"

namespace scatterlab {

// What one unit gives; the estimator fills it.
class UnitRecorder {
 public:
  // The camera value of the unit's own pixel, and the first vertex's albedo estimate and
  // normal (the film's optional layers).
  void addCamera(const Rgb& value) { camera_ += value; }
  void setFirstHit(const Rgb& albedo, const Vec3d& normal) {
    albedo_ = albedo;
    normal_ = normal;
  }
  // A value at film point `film` (pixels), before the film's 1/N.
  void splat(const Vec2d& film, const Rgb& value) { splats_.push_back({film, value}); }
  void addVertices(uint64_t count) { vertices_ += count; }
  // A subpath of the unit ended on an invalid weight (subpath.h): the film drops the unit and
  // counts it by the first such kind.
  void drop(SampleValue kind) {
    if (invalid_ == SampleValue::Valid) invalid_ = kind;
  }

 private:
  friend class SplatFilm;
  struct FilmSplat {
    Vec2d film;
    Rgb value;
  };
  void clear() {
    camera_ = albedo_ = Rgb(0.0);
    normal_ = Vec3d(0.0);
    splats_.clear();
    invalid_ = SampleValue::Valid;
  }

  Rgb camera_{0.0}, albedo_{0.0};
  Vec3d normal_{0.0};
  std::vector<FilmSplat> splats_;
  SampleValue invalid_ = SampleValue::Valid;
  uint64_t vertices_ = 0;
};

class SplatFilm {
 public:
  SplatFilm(const PinholeCamera& camera, const RenderSettings& settings);

  static constexpr int TileSize = 16, SliceSamples = 8, ChunksPerBatch = 64;
  int chunkCount() const { return tilesX_ * tilesY_ * slices_; }

  // A chunk's record, filled by one worker.
  struct Chunk {
    struct Splat {
      uint32_t pixel;
      Rgb value;
    };
    std::vector<Rgb> camera, albedo;  // per unit, pixel-major within the tile, samples in order
    std::vector<Vec3d> normal;
    std::vector<Splat> splats;    // per unit, one entry per pixel it reached
    RenderStatistics statistics;  // its vertices and dropped units
  };

  // Runs trace(x, y, sample, recorder) for every unit of chunk `index` into `chunk`.
  template <typename Trace> void traceChunk(int index, Chunk& chunk, const Trace& trace) const;
  // Adds a traced chunk to the film; chunks must come in index order.
  void add(const Chunk& chunk, int index);
  RenderResult finish(double seconds) const;

 private:
  struct Unit {
    int x0, y0, x1, y1, sample0, sample1;
  };
  Unit chunkUnits(int index) const;
  // The unit's splats spread by the filter, summed per pixel, appended to the chunk; not Valid
  // (and possibly part appended) when a splat's value or film point is not (sample_value.h).
  SampleValue spreadSplats(const UnitRecorder& unit, std::vector<Chunk::Splat>& scratch, Chunk& chunk) const;

  RenderSettings settings_;
  int width_, height_, tilesX_, tilesY_, slices_;
  struct PixelSums {
    Rgb shift{0.0}, sum{0.0}, sumSquares{0.0}, albedo{0.0};
    Vec3d normal{0.0};
    uint64_t count = 0;
    Rgb splat{0.0}, splatSquares{0.0};
  };
  std::vector<PixelSums> pixels_;
  RenderStatistics statistics_;  // vertices and dropped units
};

template <typename Trace> void SplatFilm::traceChunk(int index, Chunk& chunk, const Trace& trace) const {
  const Unit u = chunkUnits(index);
  chunk.camera.clear();
  chunk.albedo.clear();
  chunk.normal.clear();
  chunk.splats.clear();
  chunk.statistics = {};
  UnitRecorder recorder;
  std::vector<Chunk::Splat> scratch;
  for (int y = u.y0; y < u.y1; ++y)
    for (int x = u.x0; x < u.x1; ++x)
      for (int s = u.sample0; s < u.sample1; ++s) {
        recorder.clear();
        trace(x, y, s, recorder);
        const size_t splatsBefore = chunk.splats.size();
        SampleValue value = classifySample(recorder.invalid_, {recorder.camera_, recorder.albedo_});
        if (value == SampleValue::Valid) value = spreadSplats(recorder, scratch, chunk);
        if (value == SampleValue::Valid) {
          chunk.camera.push_back(recorder.camera_);
          chunk.albedo.push_back(recorder.albedo_);
          chunk.normal.push_back(recorder.normal_);
        } else {
          chunk.splats.resize(splatsBefore);
          chunk.camera.push_back(Rgb(0.0));
          chunk.albedo.push_back(Rgb(0.0));
          chunk.normal.push_back(Vec3d(0.0));
          chunk.statistics.count(value);
        }
      }
  chunk.statistics.vertices = recorder.vertices_;
}

// The render loop of a splatting estimator: trace(x, y, sample, UnitRecorder&) for every unit,
// in parallel chunks, added in order; `progress` hears the fraction of chunks done.
template <typename Trace> RenderResult renderWithSplats(const Scene& scene, const RenderSettings& settings,
                                                        const std::function<void(double)>& progress,
                                                        const Trace& trace) {
  SplatFilm film(scene.camera(), settings);
  const int chunks = film.chunkCount();
  std::vector<SplatFilm::Chunk> batch(static_cast<size_t>(SplatFilm::ChunksPerBatch));
  std::atomic<int> done{0};
  const auto start = std::chrono::steady_clock::now();
  tbb::task_arena arena(settings.threads > 0 ? settings.threads : tbb::task_arena::automatic);
  for (int first = 0; first < chunks; first += SplatFilm::ChunksPerBatch) {
    const int count = std::min(SplatFilm::ChunksPerBatch, chunks - first);
    arena.execute([&] {
      tbb::parallel_for(0, count, [&](int i) {
        film.traceChunk(first + i, batch[size_t(i)], trace);
        const int finished = ++done;
        if (progress) progress(double(finished) / chunks);
      });
    });
    for (int i = 0; i < count; ++i) film.add(batch[size_t(i)], first + i);
  }
  return film.finish(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace scatterlab
