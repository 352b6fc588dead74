#include "abut/contact/laws/tangential.hpp"

#include <algorithm>
#include <numbers>

namespace abut {

double FrictionFilter::alpha(double dt) const {
  double a = 1.0;
  switch (kind) {
    case Kind::None:
      return 1.0;
    case Kind::Simple:
      a = xfreq;
      break;
    case Kind::Period:
      a = 2.0 * std::numbers::pi * dt / xfreq;
      break;
    case Kind::Frequency:
      a = 2.0 * std::numbers::pi * xfreq * dt;
      break;
  }
  return std::clamp(a, 0.0, 1.0);  // a > 1 would overshoot: no filtering at all is the limit
}

}  // namespace abut
