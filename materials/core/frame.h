// An orthonormal frame (s, t, n): converts world directions to the local shading frame in
// which every model works (z = n = shading normal, x = s = tangent / anisotropy axis).
#pragma once

#include "materials/core/math.h"

namespace scatterlab {

template <typename T> struct Frame {
  Vec3<T> s{1, 0, 0}, t{0, 1, 0}, n{0, 0, 1};

  Frame() = default;
  Frame(const Vec3<T>& s_, const Vec3<T>& t_, const Vec3<T>& n_) : s(s_), t(t_), n(n_) {}

  // Frame around a unit normal with an arbitrary tangent: Duff et al. 2017, "Building an
  // Orthonormal Basis, Revisited" (JCGT 6(1)), branchless and continuous except at n.z = -0.
  static Frame fromNormal(const Vec3<T>& n) {
    using std::copysign;
    const T sign = copysign(T(1), n.z);
    const T a = T(-1) / (sign + n.z);
    const T b = n.x * n.y * a;
    return Frame(Vec3<T>(T(1) + sign * n.x * n.x * a, sign * b, -sign * n.x),
                 Vec3<T>(b, sign + n.y * n.y * a, -n.y), n);
  }

  // Frame with normal n and tangent as close to `tangent` as orthogonality allows
  // (Gram-Schmidt), so that an anisotropic model's x axis follows the surface's tangent.
  static Frame fromNormalTangent(const Vec3<T>& n, const Vec3<T>& tangent) {
    const Vec3<T> s = tangent - n * glm::dot(n, tangent);
    const T len2 = glm::dot(s, s);
    if (!(len2 > T(1e-20))) return fromNormal(n);
    using std::sqrt;
    const Vec3<T> sn = s / sqrt(len2);
    return Frame(sn, glm::cross(n, sn), n);
  }

  Vec3<T> toLocal(const Vec3<T>& w) const { return {glm::dot(w, s), glm::dot(w, t), glm::dot(w, n)}; }
  Vec3<T> toWorld(const Vec3<T>& w) const { return s * w.x + t * w.y + n * w.z; }
};

using Framed = Frame<double>;

}  // namespace scatterlab
