#include "sim/sph/boundaries.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "sim/parallel/thread_team.hpp"
#include "sim/state/tensor.hpp"

namespace ejecta {

namespace {

// The fields a ghost carries: those the pair passes read from neighbours (FieldSpec::halo),
// positions apart (an image is placed by its face).
std::vector<const Field*> haloFields(const ParticleSet& p) {
  std::vector<const Field*> out;
  for (const Field& f : p.fields())
    if (f.spec.halo && f.spec.name != "position" && f.storage.kind != FieldStorage::Kind::Derived)
      out.push_back(&f);
  return out;
}

// Copies the halo fields of `count` particles, the k-th from(k) to to(k), as seen through
// mirrors across the axes set in flips(k): a vector's component along a reflected axis changes
// sign, and so does a symmetric tensor's component that pairs a reflected axis with one that is
// not. Column by column (each column looked up once), the copies of a column shared among the
// threads in the same static ranges, so a column's copies need no barrier between columns. A
// source must not be among the destinations.
template <class From, class To, class Flips>
void copyHaloFields(ParticleSet& p, const std::vector<const Field*>& halo, std::size_t count,
                    From from, To to, Flips flips) {
#pragma omp parallel if (count >= kThreadTeamFrom)
  for (const Field* f : halo) {
    switch (f->storage.kind) {
      case FieldStorage::Kind::Int32: {
        std::vector<std::int32_t>& column = p.*f->storage.int32;
#pragma omp for schedule(static) nowait
        for (std::size_t k = 0; k < count; ++k) column[to(k)] = column[from(k)];
        continue;
      }
      case FieldStorage::Kind::Int64: {
        std::vector<std::int64_t>& column = p.*f->storage.int64;
#pragma omp for schedule(static) nowait
        for (std::size_t k = 0; k < count; ++k) column[to(k)] = column[from(k)];
        continue;
      }
      default: break;
    }
    for (int c = 0; c < f->spec.components; ++c) {
      std::vector<double>& column = p.column(*f, c);
      const MirrorParity parity = f->spec.parity;
      const int row = parity == MirrorParity::SymmetricTensor ? kSymRow[c] : c;
      const int col = parity == MirrorParity::SymmetricTensor ? kSymCol[c] : c;
#pragma omp for schedule(static) nowait
      for (std::size_t k = 0; k < count; ++k) {
        bool flip = false;
        if (parity == MirrorParity::Vector) flip = ((flips(k) >> c) & 1u) != 0;
        if (parity == MirrorParity::SymmetricTensor) flip = (((flips(k) >> row) ^ (flips(k) >> col)) & 1u) != 0;
        column[to(k)] = flip ? -column[from(k)] : column[from(k)];
      }
    }
  }
}

}  // namespace


Boundaries::Boundaries(Geometry geometry, const DomainBounds& domain)
    : geometry_(geometry), dim_(spatialDimension(geometry)), domain_(domain) {
  if (geometry_ == Geometry::Axisymmetric) {
    // The axis is a mirror whatever the scene says about r's lower bound.
    domain_[0].bounded = true;
    domain_[0].min = 0.0;
    domain_[0].lower = BoundaryKind::Wall;
    if (domain_[0].max <= 0.0) domain_[0].upper = BoundaryKind::Open;
  }
  for (int d = 0; d < dim_; ++d) {
    const AxisBounds& b = domain_[d];
    if (!b.bounded) continue;
    const double length = b.max - b.min;
    if (b.lower != BoundaryKind::Open)
      faces_.push_back({d, false, b.lower == BoundaryKind::Periodic, b.min, length});
    if (b.upper != BoundaryKind::Open)
      faces_.push_back({d, true, b.upper == BoundaryKind::Periodic, b.max, length});
  }
}

void Boundaries::confine(ParticleSet& p, Vec3Array* alsoFlip) const {
  if (!alsoFlip) return confine(p, std::function<void(int, std::size_t)>());
  confine(p, [alsoFlip](int d, std::size_t i) { (*alsoFlip)[d][i] = -(*alsoFlip)[d][i]; });
}

void Boundaries::confine(ParticleSet& p, const std::function<void(int, std::size_t)>& reflected) const {
  for (int d = 0; d < dim_; ++d) {
    const AxisBounds& b = domain_[d];
    if (!b.bounded) continue;
    const double length = b.max - b.min;
    std::vector<double>& x = p.x[d];
    std::vector<double>& v = p.v[d];
    auto reflect = [&](std::size_t i, double wall) {
      x[i] = 2.0 * wall - x[i];
      v[i] = -v[i];
      if (reflected) reflected(d, i);
    };
    for (std::size_t i = 0; i < p.numReal; ++i) {
      if (x[i] < b.min) {
        if (b.lower == BoundaryKind::Periodic) x[i] += length;
        else if (b.lower == BoundaryKind::Wall) reflect(i, b.min);
      } else if (x[i] >= b.max) {
        if (b.upper == BoundaryKind::Periodic) x[i] -= length;
        else if (b.upper == BoundaryKind::Wall) reflect(i, b.max);
      }
    }
  }
}

void Boundaries::makeGhosts(ParticleSet& p, double supportFactor, const Communicator* ranks) const {
  p.clearGhosts();
  flips_.clear();
  layer_.assign(faces_.size(), 0.0);
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const Face& face = faces_[f];
    const int d = face.axis;
    auto distance = [&](std::size_t i) { return faceDistance(face, p.x[d][i]); };
    // Layer: the widest support among particles whose support reaches the face the images land
    // beside: this face for a mirror; for a periodic face both this one (an image's own support)
    // and the partner face across the box (the real particles the images must serve). Includes
    // ghosts made for earlier faces, which is what fills the corners.
    const std::size_t n = p.size();
    double layer = 0.0;
#pragma omp parallel for schedule(static) if (n >= kThreadTeamFrom) reduction(max : layer)
    for (std::size_t i = 0; i < n; ++i)
      if (reachesLanding(face, p.x[d][i], supportFactor * p.h[i]))
        layer = std::max(layer, supportFactor * p.h[i]);
    if (ranks) layer = ranks->maximum(layer);
    layer_[f] = layer;
    // Images of every particle inside the layer, appended in index order: each thread lists
    // those of its static (contiguous, ascending) share, and the lists are joined in thread order.
    std::vector<std::vector<std::size_t>>& found = imagesFound_;
    found.resize(static_cast<std::size_t>(omp_get_max_threads()));
    // Room for a static share each (the first for all, should the team be one thread), so that
    // no list allocates inside the team, whose exceptions could not be thrown on.
    for (std::size_t t = 0; t < found.size(); ++t) {
      found[t].clear();
      found[t].reserve(t == 0 ? n : n / found.size() + 1);
    }
#pragma omp parallel if (n >= kThreadTeamFrom)
    {
      std::vector<std::size_t>& mine = found[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n; ++i) {
        const double dist = distance(i);
        if (dist >= 0.0 && dist < layer) mine.push_back(i);
      }
    }
    std::vector<std::size_t> images;
    for (const auto& list : found) images.insert(images.end(), list.begin(), list.end());
    const std::size_t first = p.size();
    p.resize(first + images.size());
    p.ghostSource.resize(p.numGhosts());
    flips_.resize(p.numGhosts());
    // The halo fields from each particle (itself possibly an earlier face's ghost) through this
    // face's mirror, then the images placed.
    const std::uint8_t faceFlip = face.periodic ? 0 : static_cast<std::uint8_t>(1u << d);
    copyHaloFields(
        p, haloFields(p), images.size(), [&](std::size_t k) { return images[k]; },
        [first](std::size_t k) { return first + k; }, [faceFlip](std::size_t) { return faceFlip; });
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < images.size(); ++k) {
      const std::size_t i = images[k], g = first + k;
      const std::size_t source = i < p.numReal ? i : p.ghostSource[i - p.numReal];
      std::uint8_t flips = i < p.numReal ? 0 : flips_[i - p.numReal];
      for (int c = 0; c < 3; ++c) p.x[c][g] = p.x[c][i];
      if (face.periodic) {
        p.x[d][g] += face.upper ? -face.period : face.period;
      } else {
        p.x[d][g] = 2.0 * face.position - p.x[d][i];
        flips ^= faceFlip;
      }
      p.ghostSource[g - p.numReal] = source;
      flips_[g - p.numReal] = flips;
    }
  }
}

void Boundaries::refreshGhosts(ParticleSet& p) const {
  const std::size_t nReal = p.numReal;
  copyHaloFields(
      p, haloFields(p), numBoundaryGhosts(), [&p](std::size_t g) { return p.ghostSource[g]; },
      [nReal](std::size_t g) { return nReal + g; }, [this](std::size_t g) { return flips_[g]; });
}

void Boundaries::refreshGhostTensor(const ParticleSet& p, std::vector<double>& tensor) const {
  for (std::size_t g = 0; g < numBoundaryGhosts(); ++g) {
    const double* source = &tensor[9 * p.ghostSource[g]];
    double* ghost = &tensor[9 * (p.numReal + g)];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const bool flip = (((flips_[g] >> a) ^ (flips_[g] >> b)) & 1u) != 0;
        ghost[3 * a + b] = flip ? -source[3 * a + b] : source[3 * a + b];
      }
  }
}

bool Boundaries::layersCover(const ParticleSet& p, double supportFactor) const {
  const std::size_t n = p.numReal;
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const Face& face = faces_[f];
    const double layer = layer_[f];
    const double* x = p.x[face.axis].data();
    bool covered = true;
#pragma omp parallel for schedule(static) if (n >= kThreadTeamFrom) reduction(&& : covered)
    for (std::size_t i = 0; i < n; ++i) {
      const double reach = supportFactor * p.h[i];
      if (reach > layer && reachesLanding(face, x[i], reach)) covered = false;
    }
    if (!covered) return false;
  }
  return true;
}

}  // namespace ejecta
