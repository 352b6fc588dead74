// The band test of penetration_zone.hpp.
#include "abut/contact/penetration_zone.hpp"

#include <algorithm>
#include <cmath>

namespace abut {

FacetBand facet_band(const QuadCorners& c) {
  FacetBand band;
  for (int i = 0; i < 3; ++i) {
    band.lo[i] = std::min({c[0][i], c[1][i], c[2][i], c[3][i]});
    band.hi[i] = std::max({c[0][i], c[1][i], c[2][i], c[3][i]});
  }
  const Vec3 a = (c[1] - c[0] + c[2] - c[3]) * 0.25;
  const Vec3 b = (c[3] - c[0] + c[2] - c[1]) * 0.25;
  const Vec3 h = (c[0] - c[1] + c[2] - c[3]) * 0.25;
  const Vec3 axb = cross(a, b);
  const double area = norm(axb);
  if (!(area > 0.0)) return band;
  // The local normal deviates from a x b by xi u + eta v, largest at a corner.
  const Vec3 u = cross(a, h), v = cross(h, b);
  band.tilt = std::max(norm(u + v), norm(u - v)) / area;
  band.normal = axb / area;
  band.centre = (c[0] + c[1] + c[2] + c[3]) * 0.25;
  for (const Vec3& corner : c) band.radius = std::max(band.radius, norm(corner - band.centre));
  band.warp = std::abs(dot(h, band.normal));
  band.usable = band.tilt <= 0.5;
  return band;
}

double band_slack(const FacetBand& band, const Vec3& x) {
  constexpr double kRoundOff = 1e-9, kCoordinateRoundOff = 1e-13;
  const double rho = norm(x - band.centre) + band.radius;
  const double magnitude =
      std::abs(band.centre.x) + std::abs(band.centre.y) + std::abs(band.centre.z);
  return band.warp + rho * band.tilt + kRoundOff * rho + kCoordinateRoundOff * magnitude;
}

bool outside_penetration_zone(const FacetBand& band, const Vec3& x, double g, double below,
                              double reach) {
  if (box_distance2(band.lo, band.hi, x) > reach * reach) return true;  // (a)
  if (!band.usable) return false;
  const double s = dot(x - band.centre, band.normal);
  const double sigma = band_slack(band, x);
  return s >= g + sigma || s < std::min(g - below, -g) - sigma;  // (b)
}

bool surely_behind(const FacetBand& band, const Vec3& x) {
  return band.usable && dot(x - band.centre, band.normal) < -band_slack(band, x);
}

}  // namespace abut
