#include "multibody/spline_grid.h"

#include "autodiff.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace bdfcar::mb {

namespace {

// Slopes at the nodes of the natural cubic spline through f (spacing h):
// second derivatives M from the tridiagonal system (M = 0 at both ends), then
// the spline's derivative at each node. A cubic Hermite patch with these
// slopes is the spline itself.
std::vector<double> naturalSplineSlopes(const std::vector<double>& f, double h) {
  const int n = static_cast<int>(f.size());
  std::vector<double> M(n, 0.0), c(n, 0.0), d(n, 0.0);
  // Rows 1..n-2: M[i-1] + 4 M[i] + M[i+1] = 6 (f[i+1] - 2 f[i] + f[i-1]) / h^2 (Thomas algorithm).
  for (int i = 1; i < n - 1; ++i) {
    const double rhs = 6.0 * (f[i + 1] - 2.0 * f[i] + f[i - 1]) / (h * h);
    const double denom = 4.0 - (i > 1 ? c[i - 1] : 0.0);
    c[i] = 1.0 / denom;
    d[i] = (rhs - (i > 1 ? d[i - 1] : 0.0)) / denom;
  }
  for (int i = n - 2; i >= 1; --i) M[i] = d[i] - c[i] * M[i + 1];
  std::vector<double> slope(n);
  for (int i = 0; i < n - 1; ++i) slope[i] = (f[i + 1] - f[i]) / h - h * (2.0 * M[i] + M[i + 1]) / 6.0;
  slope[n - 1] = (f[n - 1] - f[n - 2]) / h + h * (M[n - 2] + 2.0 * M[n - 1]) / 6.0;
  return slope;
}

// Cubic Hermite weights on one cell for the value, first and second
// derivative: [node 0 value, node 0 slope, node 1 value, node 1 slope].
template <typename T>
struct HermiteWeights {
  std::array<T, 4> w0, w1, w2;
};

template <typename T>
HermiteWeights<T> hermite(const T& u, double h) {
  const T u2 = u * u, u3 = u2 * u;
  HermiteWeights<T> w;
  w.w0 = {2 * u3 - 3 * u2 + 1, (u3 - 2 * u2 + u) * h, -2 * u3 + 3 * u2, (u3 - u2) * h};
  w.w1 = {(6 * u2 - 6 * u) / h, 3 * u2 - 4 * u + 1, (-6 * u2 + 6 * u) / h, 3 * u2 - 2 * u};
  w.w2 = {(12 * u - 6) / (h * h), (6 * u - 4) / h, (-12 * u + 6) / (h * h), (6 * u - 2) / h};
  return w;
}

// A cubic Hermite patch on one cell: weights w (one row of HermiteWeights)
// against node a's value and slope, then node b's.
template <typename T>
inline T hermiteSum(const std::array<T, 4>& w, const double* a, const double* b) {
  return w[0] * a[0] + w[1] * a[1] + w[2] * b[0] + w[3] * b[1];
}

// Cell index and local coordinate of x, clamped to the grid; ex = distance outside.
template <typename T>
int locate(const GridAxis& a, const T& x, T& u, T& ex, bool& outside) {
  const T xc = ad::clamp(x, a.start, a.end());
  ex = x - xc;
  outside = ad::value(ex) != 0.0;
  const int cell = std::clamp(static_cast<int>(std::floor((ad::value(xc) - a.start) / a.step)), 0, a.nodes - 2);
  u = (xc - (a.start + cell * a.step)) / a.step;
  return cell;
}

void checkAxis(const GridAxis& a, const char* name, bool mayBeSingle) {
  const bool single = mayBeSingle && a.nodes == 1;
  if (!single && (a.nodes < 3 || !(a.step > 0) || !std::isfinite(a.start) || !std::isfinite(a.step)))
    throw std::invalid_argument(std::string("spline grid: axis ") + name +
                                " needs at least 3 nodes, a finite start and a positive step");
}

}  // namespace

SplineGrid::SplineGrid(const GridAxis& x, const GridAxis& y, const std::vector<std::vector<double>>& samples)
    : x_(x), y_(y), components_(static_cast<int>(samples.size())), nodes_(x.nodes * y.nodes) {
  checkAxis(x_, "x", false);
  checkAxis(y_, "y", true);
  if (components_ < 1 || components_ > kMaxComponents)
    throw std::invalid_argument("spline grid: 1 to " + std::to_string(kMaxComponents) + " components");
  data_.assign(static_cast<size_t>(components_) * nodes_ * 4, 0.0);
  for (int c = 0; c < components_; ++c) {
    const std::vector<double>& s = samples[c];
    if (static_cast<int>(s.size()) != nodes_) throw std::invalid_argument("spline grid: wrong number of samples");
    for (double v : s)
      if (!std::isfinite(v)) throw std::invalid_argument("spline grid: a sample is not finite");
    auto at = [&](int i, int j, int k) -> double& {
      return data_[(static_cast<size_t>(c) * nodes_ + i + x_.nodes * j) * 4 + k];
    };
    // Values, then slopes along x (each row), along y (each column), and the
    // cross derivative as the y-slopes of the x-slopes.
    std::vector<double> line;
    for (int j = 0; j < y_.nodes; ++j) {
      line.assign(s.begin() + x_.nodes * j, s.begin() + x_.nodes * (j + 1));
      const std::vector<double> fx = naturalSplineSlopes(line, x_.step);
      for (int i = 0; i < x_.nodes; ++i) {
        at(i, j, 0) = line[i];
        at(i, j, 1) = fx[i];
      }
    }
    if (y_.nodes == 1) continue;
    for (int i = 0; i < x_.nodes; ++i) {
      for (int k : {0, 1}) {
        line.resize(y_.nodes);
        for (int j = 0; j < y_.nodes; ++j) line[j] = at(i, j, k);
        const std::vector<double> fy = naturalSplineSlopes(line, y_.step);
        for (int j = 0; j < y_.nodes; ++j) at(i, j, k == 0 ? 2 : 3) = fy[j];
      }
    }
  }
}

template <typename T>
void SplineGrid::eval(const T& x, double y, SampleT<T>& out) const {
  T ux, ex;
  double uy = 0, ey = 0;
  bool outX, outY = false;
  const int i = locate(x_, x, ux, ex, outX);
  const HermiteWeights<T> wx = hermite(ux, x_.step);
  if (y_.nodes == 1) {
    for (int c = 0; c < components_; ++c) {
      const double* a = node(c, i);
      const double* b = node(c, i + 1);
      const T g = hermiteSum(wx.w0, a, b), gx = hermiteSum(wx.w1, a, b), gxx = hermiteSum(wx.w2, a, b);
      out.f[c] = g + ex * gx;
      out.grad[c] = {gx, T(0.0)};
      out.hess[c] = {outX ? T(0.0) : gxx, T(0.0), T(0.0)};
    }
    out.outside = outX;
    return;
  }
  const int j = locate(y_, y, uy, ey, outY);
  const HermiteWeights<double> wy = hermite(uy, y_.step);
  // Node (a, b) of the cell, a, b in {0, 1}: its x weights use entries 2a, 2a+1.
  for (int c = 0; c < components_; ++c) {
    T g = T(0.0), gx = T(0.0), gy = T(0.0), gxx = T(0.0), gxy = T(0.0), gyy = T(0.0);
    for (int b = 0; b < 2; ++b) {
      for (int a = 0; a < 2; ++a) {
        const double* n = node(c, (i + a) + x_.nodes * (j + b));
        // n = f, fx, fy, fxy; x weight for f/fy: w[2a], for fx/fxy: w[2a+1]; y likewise with b.
        const T &vx0 = wx.w0[2 * a], &dx0 = wx.w0[2 * a + 1];
        const T &vx1 = wx.w1[2 * a], &dx1 = wx.w1[2 * a + 1];
        const T &vx2 = wx.w2[2 * a], &dx2 = wx.w2[2 * a + 1];
        const double vy0 = wy.w0[2 * b], dy0 = wy.w0[2 * b + 1];
        const double vy1 = wy.w1[2 * b], dy1 = wy.w1[2 * b + 1];
        const double vy2 = wy.w2[2 * b], dy2 = wy.w2[2 * b + 1];
        auto term = [&](const T& X_f, const T& X_d, double Y_f, double Y_d) -> T {
          return X_f * Y_f * n[0] + X_d * Y_f * n[1] + X_f * Y_d * n[2] + X_d * Y_d * n[3];
        };
        g += term(vx0, dx0, vy0, dy0);
        gx += term(vx1, dx1, vy0, dy0);
        gy += term(vx0, dx0, vy1, dy1);
        gxx += term(vx2, dx2, vy0, dy0);
        gxy += term(vx1, dx1, vy1, dy1);
        gyy += term(vx0, dx0, vy2, dy2);
      }
    }
    out.f[c] = g + ex * gx + ey * gy + ex * ey * gxy;
    out.grad[c] = {T(gx + ey * gxy), T(gy + ex * gxy)};
    out.hess[c] = {outX ? T(0.0) : gxx, gxy, outY ? T(0.0) : gyy};
  }
  out.outside = outX || outY;
}

SplineGrid::CurvePoint SplineGrid::curvePoint(double x) const {
  CurvePoint p;
  double u;
  p.cell = locate(x_, x, u, p.ex, p.outside);
  const HermiteWeights<double> w = hermite(u, x_.step);
  p.w0 = w.w0;
  p.w1 = w.w1;
  p.w2 = w.w2;
  return p;
}

void SplineGrid::evalCurve(const CurvePoint& at, Curve& out) const {
  if (y_.nodes != 1) throw std::logic_error("spline grid: evalCurve on a grid of two coordinates");
  for (int c = 0; c < components_; ++c) {
    const double* a = node(c, at.cell);
    const double* b = node(c, at.cell + 1);
    const double g = hermiteSum(at.w0, a, b), gx = hermiteSum(at.w1, a, b), gxx = hermiteSum(at.w2, a, b);
    out.f[c] = g + at.ex * gx;
    out.df[c] = gx;
    out.ddf[c] = at.outside ? 0.0 : gxx;
  }
  out.outside = at.outside;
}

// The cubic along x of a cell from its end values P0, P1 and x-slopes Q0, Q1
// (Hermite data): value c0 + c1 u + c2 u^2 + c3 u^3 over u = (x - x_i) / h,
// with its x-slope's and curvature's coefficients (what eval's weights sum).
void SplineGrid::RowCache::setCubic(double* c, double P0, double Q0, double P1, double Q1, double h, bool derivatives) {
  const double c1 = h * Q0, c2 = 3 * (P1 - P0) - h * (2 * Q0 + Q1), c3 = 2 * (P0 - P1) + h * (Q0 + Q1);
  c[0] = P0;
  c[1] = c1;
  c[2] = c2;
  c[3] = c3;
  if (!derivatives) return;
  c[4] = c1 / h;
  c[5] = 2 * c2 / h;
  c[6] = 3 * c3 / h;
  c[7] = 2 * c2 / (h * h);
  c[8] = 6 * c3 / (h * h);
}

template <typename T>
void SplineGrid::eval(const T& x, double y, RowCache& cache, SampleT<T>& out) const {
  T ux, ex;
  bool outX;
  const int i = locate(x_, x, ux, ex, outX);
  const bool twoD = y_.nodes > 1;
  if (i != cache.i || y != cache.y || cache.j < 0) {
    // The cell's nodes contracted along y (value and x-slope at each x
    // node, per order of the y derivative), then as cubics along x.
    std::array<std::array<double, 2>, 3> P0{}, P1{};  // [k] = {value, x-slope} at nodes i, i + 1
    double uy = 0;
    int j = 0;
    cache.ey = 0;
    cache.outY = false;
    if (twoD) j = locate(y_, y, uy, cache.ey, cache.outY);
    const HermiteWeights<double> wy = twoD ? hermite(uy, y_.step) : HermiteWeights<double>{};
    const std::array<double, 4>* wk[3] = {&wy.w0, &wy.w1, &wy.w2};
    for (int c = 0; c < components_; ++c) {
      for (int a = 0; a < 2; ++a) {
        std::array<std::array<double, 2>, 3>& P = a == 0 ? P0 : P1;
        const double* n0 = node(c, (i + a) + x_.nodes * j);
        if (!twoD) {
          P[0] = {n0[0], n0[1]};
          continue;
        }
        const double* n1 = node(c, (i + a) + x_.nodes * (j + 1));
        for (int k = 0; k < 3; ++k) {
          const std::array<double, 4>& w = *wk[k];  // node j: w[0] value, w[1] slope; node j + 1: w[2], w[3]
          P[k] = {w[0] * n0[0] + w[1] * n0[2] + w[2] * n1[0] + w[3] * n1[2],
                  w[0] * n0[1] + w[1] * n0[3] + w[2] * n1[1] + w[3] * n1[3]};
        }
      }
      double* cc = cache.cubics[c].data();
      RowCache::setCubic(cc, P0[0][0], P0[0][1], P1[0][0], P1[0][1], x_.step, true);
      if (!twoD) continue;
      RowCache::setCubic(cc + 9, P0[1][0], P0[1][1], P1[1][0], P1[1][1], x_.step, true);
      RowCache::setCubic(cc + 16, P0[2][0], P0[2][1], P1[2][0], P1[2][1], x_.step, false);
    }
    cache.y = y;
    cache.i = i;
    cache.j = j;
  }
  const T& u = ux;
  const double ey = cache.ey;
  for (int c = 0; c < components_; ++c) {
    const double* v = cache.cubics[c].data();
    const T g = v[0] + u * (v[1] + u * (v[2] + u * v[3]));
    const T gx = v[4] + u * (v[5] + u * v[6]);
    const T gxx = v[7] + u * v[8];
    if (!twoD) {
      out.f[c] = g + ex * gx;
      out.grad[c] = {gx, T(0.0)};
      out.hess[c] = {outX ? T(0.0) : gxx, T(0.0), T(0.0)};
      continue;
    }
    const T gy = v[9] + u * (v[10] + u * (v[11] + u * v[12]));
    const T gxy = v[13] + u * (v[14] + u * v[15]);
    const T gyy = v[16] + u * (v[17] + u * (v[18] + u * v[19]));
    out.f[c] = g + ex * gx + ey * gy + ex * ey * gxy;
    out.grad[c] = {T(gx + ey * gxy), T(gy + ex * gxy)};
    out.hess[c] = {outX ? T(0.0) : gxx, gxy, cache.outY ? T(0.0) : gyy};
  }
  out.outside = outX || cache.outY;
}

template void SplineGrid::eval(const double&, double, SampleT<double>&) const;
template void SplineGrid::eval(const double&, double, RowCache&, SampleT<double>&) const;
template void SplineGrid::eval(const ad::DualN<2>&, double, RowCache&, SampleT<ad::DualN<2>>&) const;

}  // namespace bdfcar::mb
