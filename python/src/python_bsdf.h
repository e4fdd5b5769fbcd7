// A BSDF written in Python, as the kit sees it (docs/python.md, "The kit on any object"): any
// object with eval(wi, wo), pdf(wi, wo) and sample(wi, u_lobe, u) on numpy arrays, with the
// signatures of scatterlab's own materials, and optional attributes saying what it is. Its
// answers to the kit's queries come in batches (ReplayedBsdf).
#pragma once

#include <span>
#include <vector>

#include <pybind11/pybind11.h>

#include "python/src/replayed_bsdf.h"

namespace scatterlab::python {

class PythonBsdf {
 public:
  // Reads the optional attributes (lossless, lossless_accuracy, delta, transmission,
  // reciprocal); TypeError
  // when eval, pdf or sample is missing, ValueError for an attribute of the wrong kind.
  explicit PythonBsdf(pybind11::object object);

  const DeclaredProperties& declared() const { return declared_; }
  // Answers `misses` by calling the object, in batches of at most BatchRows rows, and stores the
  // answers in `model`. ValueError naming the method when it returns the wrong shape. The GIL
  // must be held.
  void answer(ReplayedBsdf& model, const ReplayedBsdf::Misses& misses) const;

  // f[k] and pdf[k] of the object at (wi[k], wo[k]) for every k, called in batches of at most
  // BatchRows rows (the kit's quadratures, ReplayedBsdf). The GIL must be held.
  void evalAndPdf(std::span<const Vec3d> wi, std::span<const Vec3d> wo, std::span<Rgb> f,
                  std::span<double> pdf) const;

  // Rows per call into Python: large enough that numpy's per-call cost vanishes, small enough
  // that one batch's arrays (about 100 bytes a row) stay near 100 MB.
  static constexpr size_t BatchRows = size_t(1) << 20;

 private:
  void answerEvals(ReplayedBsdf& model, const std::vector<Miss>& evals) const;
  void answerPdfs(ReplayedBsdf& model, const std::vector<Miss>& pdfs) const;
  void answerSamples(ReplayedBsdf& model, const std::vector<Miss>& samples) const;

  pybind11::object object_;
  DeclaredProperties declared_;
};

}  // namespace scatterlab::python
