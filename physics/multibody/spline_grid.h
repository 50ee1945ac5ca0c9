// A smooth function of one or two coordinates tabulated on a uniform grid:
// tensor-product cubic splines with natural ends (C2 along each coordinate),
// several components sharing the grid. Used for kinematics derived from a
// linkage (a wheel carrier's pose as a function of travel and rack), where
// Newton needs values, gradients and second derivatives that are smooth.
//
// Beyond the grid the function continues as its first-order expansion at the
// nearest grid point, f + ex fx + ey fy + ex ey fxy (ex, ey: the distances
// outside): C1 everywhere, and C2 along a coordinate because a natural
// spline's second derivative is zero at its ends. Second derivatives out
// there leave out third-order terms (ey fxxy): outside the grid is a fallback
// the caller reports, not a region to work in.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace bdfcar::mb {

struct GridAxis {
  double start = 0, step = 1;  // first node and spacing (step > 0)
  int nodes = 0;               // at least 3
  double end() const { return start + step * (nodes - 1); }
};

class SplineGrid {
 public:
  static constexpr int kMaxComponents = 12;

  // One value of the function (every component) and its derivatives; T
  // double, or a Dual (autodiff.h) where x is a dual number (a closed
  // form's Jacobian: the derivatives' own derivatives along x follow).
  template <typename T>
  struct SampleT {
    std::array<T, kMaxComponents> f{};
    std::array<std::array<T, 2>, kMaxComponents> grad{};  // d/dx, d/dy
    std::array<std::array<T, 3>, kMaxComponents> hess{};  // xx, xy, yy
    bool outside = false;                                   // beyond the grid
  };
  using Sample = SampleT<double>;

  SplineGrid() = default;
  // samples[c][i + x.nodes * j]: component c at node (i, j); for one
  // coordinate y.nodes == 1. Throws std::invalid_argument on bad sizes.
  SplineGrid(const GridAxis& x, const GridAxis& y, const std::vector<std::vector<double>>& samples);

  int dimensions() const { return y_.nodes > 1 ? 2 : 1; }
  int components() const { return components_; }
  const GridAxis& axisX() const { return x_; }
  const GridAxis& axisY() const { return y_; }

  // Every component at (x, y); y is ignored for one coordinate. No
  // allocation. T double or ad::DualN<2> (spline_grid.cpp).
  template <typename T>
  void eval(const T& x, double y, SampleT<T>& out) const;

  // One coordinate (dimensions() == 1) along x: where x is on the axis (its
  // cell and the cubic's weights there), which serves every grid on an equal
  // axis (sameAxisX), and every component's value and first and second
  // derivatives there. The same numbers as eval's, without the y terms.
  struct CurvePoint {
    int cell = 0;
    double ex = 0;         // x beyond the grid
    bool outside = false;
    std::array<double, 4> w0{}, w1{}, w2{};  // value, slope, curvature weights of the cell's nodes
  };
  struct Curve {
    std::array<double, kMaxComponents> f{}, df{}, ddf{};
    bool outside = false;
  };
  CurvePoint curvePoint(double x) const;
  void evalCurve(const CurvePoint& at, Curve& out) const;
  bool sameAxisX(const SplineGrid& o) const { return x_.start == o.x_.start && x_.step == o.x_.step && x_.nodes == o.x_.nodes; }

  // The same for many x at one y (a closed-form car's table over travel
  // and rack at one step's rack travel, or over travel alone): the cell's
  // nodes contracted along y once, and each component's cubics along x in
  // that cell kept in the cache while x stays in the cell and y is the
  // same; each evaluation is then a few polynomials in x. Equal to eval up
  // to rounding (the sums are taken in another order).
  struct RowCache {
    double y = 0;
    int i = -1, j = -1;              // the cell contracted (-1: none)
    double ey = 0;                   // y beyond the grid
    bool outY = false;
    // Per component, along x over the cell's local coordinate u: the cubic
    // of the value (4 coefficients) with those of its x-slope (3) and
    // curvature (2); of the y-slope (4) with its x-slope's (3); of the
    // y-curvature (4).
    std::array<std::array<double, 20>, kMaxComponents> cubics{};
    static void setCubic(double* c, double P0, double Q0, double P1, double Q1, double h, bool derivatives);
  };
  template <typename T>
  void eval(const T& x, double y, RowCache& cache, SampleT<T>& out) const;

 private:
  // Node data of component c at node n: f, fx, fy, fxy.
  const double* node(int c, int n) const { return &data_[(static_cast<std::size_t>(c) * nodes_ + n) * 4]; }

  GridAxis x_, y_;
  int components_ = 0, nodes_ = 0;
  std::vector<double> data_;
};

}  // namespace bdfcar::mb
