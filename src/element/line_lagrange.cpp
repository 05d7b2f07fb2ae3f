#include "element/line_lagrange.h"

namespace homesh {

void line_lagrange(int p, double t, double* L, double* dL) {
  const double pt = p * t;
  for (int i = 0; i <= p; ++i) {
    double value = 1.0, derivative = 0.0;
    for (int s = 0; s <= p; ++s) {
      if (s == i) continue;
      const double f = (pt - s) / (i - s), df = static_cast<double>(p) / (i - s);
      derivative = derivative * f + value * df;
      value *= f;
    }
    L[i] = value;
    dL[i] = derivative;
  }
}

}  // namespace homesh
