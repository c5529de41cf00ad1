#pragma once
// Distance axes over a flat picture (plane and RZ views): ticks at round lengths along the
// bottom and left edges of the plot, labelled in metres, with the axes' names ("x [m]", RZ
// "r [m]" and "z [m]"). Asked for with Annotations::axes; a perspective view has none (no one
// length per pixel across the picture).
#include <string>

#include "render/image.hpp"
#include "render/view_transform.hpp"

namespace ejecta::render {

struct AxisNames {
  std::string horizontal = "x", vertical = "y";
};

// Draws into the plot rows [0, framing.plotHeight) of `image`. Does nothing for a perspective
// framing.
void drawDistanceAxes(Image& image, const Framing& framing, const AxisNames& names, int textScale, Rgba8 ink);

}  // namespace ejecta::render
