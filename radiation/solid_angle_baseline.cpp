#include "radiation/solid_angle_baseline.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ejecta::radiation {

using namespace vec3;

double seedSolidAngle(double l, double r) {
  if (!(r > 0.0)) throw std::invalid_argument("seed solid angle: the distance must be > 0");
  return l / (r * r);
}

BaselineResult seedBaseline(const Emitters& emitters, const Vec3& centre, const Vec3& normal,
                            double side, const BaselineOptions& options) {
  if (!finite(centre) || !finite(normal) || norm(normal) == 0.0)
    throw std::invalid_argument("seed baseline: the receiver needs a finite centre and normal");
  const Vec3 n = normalized(normal);
  const double l = options.receiverSide > 0.0 ? options.receiverSide : side;
  if (options.length == BaselineLength::ReceiverSide && !(l > 0.0))
    throw std::invalid_argument("seed baseline: the receiver side length must be > 0");
  BaselineResult out;
  for (std::size_t i = 0; i < emitters.size(); ++i) {
    const Vec3 d = sub(Vec3{emitters.x[i], emitters.y[i], emitters.z[i]}, centre);
    if (options.frontOnly && !(dot(d, n) > 0.0)) continue;
    const double r = norm(d);
    if (!(r > 0.0))
      throw std::invalid_argument("seed baseline: emitter " + std::to_string(i) +
                                  " sits at the receiver's centre");
    const double li = options.length == BaselineLength::ReceiverSide ? l : 2.0 * emitters.radius[i];
    const double omega = seedSolidAngle(li, r);
    out.solidAngleSum += omega;
    out.flux += omega * emitters.exitance(i);
    ++out.counted;
  }
  return out;
}

BaselineResult seedBaseline(const Emitters& emitters, const TriangleMesh& mesh, std::size_t patch,
                            const BaselineOptions& options) {
  if (patch >= mesh.patchCount())
    throw std::invalid_argument("seed baseline: no patch " + std::to_string(patch));
  const double area = mesh.patchArea(patch);
  if (!(area > 0.0))
    throw std::invalid_argument("seed baseline: patch '" + mesh.patchNames[patch] + "' has no area");
  const Vec3 normal = mesh.patchNormal(patch);
  if (norm(normal) > 0.0)
    return seedBaseline(emitters, mesh.patchCentroid(patch), normal, std::sqrt(area), options);
  // A closed patch (a whole mesh spacecraft given as one patch) faces every way: its summed
  // normal vanishes. The seed's sum (eq. 4.7) then counts every emitter, in front or not.
  BaselineOptions everyWay = options;
  everyWay.frontOnly = false;
  return seedBaseline(emitters, mesh.patchCentroid(patch), Vec3{1.0, 0.0, 0.0}, std::sqrt(area), everyWay);
}

}  // namespace ejecta::radiation
