#pragma once
// Domain boundaries: open, periodic and reflecting walls, and the RZ axis (a mirror at r = 0).
// Walls and periodic faces act through ghost particles: mirror images (position reflected,
// normal velocity reversed) or periodic images of the real particles near each face. Ghosts are
// rebuilt every step after the drift and carry copies of their sources' state.
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "sim/parallel/communicator.hpp"
#include "sim/state/particles.hpp"
#include "sim/state/domain.hpp"
#include "sim/state/geometry.hpp"

namespace ejecta {

class Boundaries {
 public:
  Boundaries(Geometry geometry, const DomainBounds& domain);

  // Brings real particles back inside: periodic wrap, and specular reflection of any particle
  // that crossed a wall or the axis during the drift. `alsoFlip`, when given, is a second
  // velocity array (the leapfrog's half-step velocity) reflected together with p.v.
  void confine(ParticleSet& p, Vec3Array* alsoFlip = nullptr) const;
  // The same, calling reflected(axis, i) for each particle i reflected across `axis` (individual
  // time steps flip the particle's stored start velocity and acceleration there too).
  void confine(ParticleSet& p, const std::function<void(int, std::size_t)>& reflected) const;

  // Drops old ghosts and adds images of the real particles lying within the ghost layer of each
  // wall and periodic face (and of earlier ghosts, so corners are covered). The layer of a face
  // reaches `supportFactor * h` beyond the largest h found near it. Copies all primary and EOS
  // state to the ghosts. In a distributed run (`ranks` given) each face's layer is the widest
  // over all ranks, so that every rank images what another rank's particles near the face need.
  void makeGhosts(ParticleSet& p, double supportFactor, const Communicator* ranks = nullptr) const;
  // The ghosts the last makeGhosts made (the first numGhosts() after the real particles; halos
  // from other ranks may follow them).
  std::size_t numBoundaryGhosts() const { return flips_.size(); }

  // Recopies per-particle fields from sources to this set's ghosts (after the density pass
  // changed them).
  void refreshGhosts(ParticleSet& p) const;

  // Copies a full (not symmetric) 3 x 3 tensor per particle, stored row-major at 9 i, from
  // sources to the ghosts of the last makeGhosts: a mirror reverses the components that pair a
  // reflected axis with one that is not (a velocity gradient dv_a/dx_b changes sign with v_a and
  // with x_b).
  void refreshGhostTensor(const ParticleSet& p, std::vector<double>& tensor) const;

  // True if every real particle's kernel support (supportFactor * h) near a face lies inside the
  // ghost layer built by the last makeGhosts; false means makeGhosts must run again.
  bool layersCover(const ParticleSet& p, double supportFactor) const;


 private:
  struct Face {
    int axis;
    bool upper;        // face at max (true) or min (false)
    bool periodic;     // periodic image (shift) or mirror (reflection)
    double position;   // coordinate of the face
    double period;     // box length, periodic faces only
  };
  // Signed distance of coordinate x inside the face (positive inside the domain). Inline: it
  // runs for every particle and face at every (sub-)step.
  static double faceDistance(const Face& face, double x) {
    return face.upper ? face.position - x : x - face.position;
  }
  // True if a particle at x with support `reach` needs this face's images: it reaches the face
  // (or, for a periodic face, the partner face where the images land).
  static bool reachesLanding(const Face& face, double x, double reach) {
    if (faceDistance(face, x) < reach) return true;
    if (!face.periodic) return false;
    // The partner face: images of particles near this face are shifted across to it.
    const double partner = face.upper ? face.position - face.period : face.position + face.period;
    const double toPartner = face.upper ? x - partner : partner - x;
    return toPartner < reach;
  }

  Geometry geometry_;
  int dim_;
  DomainBounds domain_;
  std::vector<Face> faces_;
  mutable std::vector<double> layer_;      // layer width per face from the last makeGhosts
  mutable std::vector<std::uint8_t> flips_; // per ghost: bit d set = velocity component d reversed
  mutable std::vector<std::vector<std::size_t>> imagesFound_;  // makeGhosts' scratch, per thread
};

}  // namespace ejecta
