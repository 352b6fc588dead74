#include "abut/material/elastic.hpp"

namespace abut {

LameConstants lame_constants(const ElasticParams& p) {
  return {p.young * p.poisson / ((1.0 + p.poisson) * (1.0 - 2.0 * p.poisson)),
          p.young / (2.0 * (1.0 + p.poisson))};
}

}  // namespace abut
