#include "solver/landing_balance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "model/mesh_pieces.hpp"
#include "model/model.hpp"

namespace dinam {
namespace {

using Point = Eigen::Vector2d;

double cross(const Point& o, const Point& a, const Point& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// The convex hull of `points`, counter-clockwise, without collinear points (Andrew's monotone
// chain); one or two points where they are all one point or on one line.
std::vector<Point> convex_hull(std::vector<Point> points) {
  std::sort(points.begin(), points.end(), [](const Point& a, const Point& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) {
    return points;
  }
  std::vector<Point> hull(2 * points.size());
  std::size_t k = 0;
  for (const Point& p : points) {  // the lower chain
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0) {
      --k;
    }
    hull[k++] = p;
  }
  const std::size_t lower = k + 1;
  for (auto p = points.rbegin() + 1; p != points.rend(); ++p) {  // the upper chain
    while (k >= lower && cross(hull[k - 2], hull[k - 1], *p) <= 0.0) {
      --k;
    }
    hull[k++] = *p;
  }
  hull.resize(k - 1);  // the last point is the first
  return hull;
}

// The point of the segment ab nearest q.
Point nearest_on_segment(const Point& q, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double length_squared = ab.squaredNorm();
  const double t =
      length_squared > 0.0 ? std::clamp((q - a).dot(ab) / length_squared, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

// Where q stands against the convex polygon `hull` (counter-clockwise): how far inside it, from
// its nearest edge (negative outside), the point of its boundary nearest q, over which a piece
// whose centre of mass stands at q tips, and that edge's outward normal (either way for a base
// of two points, none for one).
struct Standing {
  double depth = 0.0;
  Point edge = Point::Zero();
  Point outward = Point::Zero();
  bool either_way = false;
};

Standing standing(const Point& q, const std::vector<Point>& hull) {
  if (hull.size() < 3) {
    const Point& a = hull.front();
    const Point& b = hull.back();
    const Point edge = nearest_on_segment(q, a, b);
    const Point along = b - a;
    const Point outward =
        along.isZero() ? Point::Zero() : Point(along.y(), -along.x()).normalized();
    return {-(q - edge).norm(), edge, outward, true};
  }
  Standing nearest{std::numeric_limits<double>::infinity()};
  bool inside = true;
  for (std::size_t e = 0; e < hull.size(); ++e) {
    const Point& a = hull[e];
    const Point& b = hull[(e + 1) % hull.size()];
    inside = inside && cross(a, b, q) >= 0.0;
    const Point edge = nearest_on_segment(q, a, b);
    const double distance = (q - edge).norm();
    if (distance < nearest.depth) {
      nearest = {distance, edge, Point(b.y() - a.y(), a.x() - b.x()).normalized(), false};
    }
  }
  nearest.depth = inside ? nearest.depth : -nearest.depth;
  return nearest;
}

// How the pieces of a model land on its ground, seen along gravity.
class Landing {
 public:
  explicit Landing(const Model& model)
      : model_(model),
        ground_(model.ground),
        down_(model.gravity.normalized()),
        across_(ground_.normal.unitOrthogonal()),
        along_(ground_.normal.cross(across_)) {}

  PieceLanding of(std::span<const Index> nodes) {
    const std::vector<Vec3>& x = model_.node_initial_x;
    Vec3 low = x[nodes.front()];
    Vec3 high = low;
    Vec3 moment = Vec3::Zero();
    double mass = 0.0;
    Index lowest = nodes.front();
    for (const Index i : nodes) {
      low = low.cwiseMin(x[i]);
      high = high.cwiseMax(x[i]);
      moment += model_.node_mass[i] * x[i];
      mass += model_.node_mass[i];
      if (ground_.clearance(i, x[i]) < ground_.clearance(lowest, x[lowest])) {
        lowest = i;
      }
    }
    const double size = (high - low).norm();
    const double rounding = 1e-9 * size;
    const double bottom = ground_.clearance(lowest, x[lowest]);
    base_.clear();
    for (const Index i : nodes) {
      if (ground_.clearance(i, x[i]) <= bottom + kBaseTolerance * size) {
        base_.push_back(on_plane(x[i]));
      }
    }
    const Vec3 centre = moment / mass;
    const Point q = on_plane(centre);
    const Standing stands = standing(q, convex_hull(base_));
    const double height = (centre - x[lowest]).dot(ground_.normal);  // over the base
    PieceLanding landing;
    landing.node = lowest;
    // A piece whose centre lies level with its base (a plate, a wire lying flat) stands where its
    // centre is within the base to rounding.
    landing.tipping_degrees = height > rounding ? degrees(std::atan2(stands.depth, height))
                              : stands.depth >= -rounding ? 90.0
                                                          : -90.0;
    // It tips over the edge nearest its centre, outwards: away from the centre where the centre
    // is inside, towards it where outside; where the centre stands on the edge itself (a plate on
    // its edge, a ring on its rim), along the edge's normal, either way for an edge of two nodes,
    // any way for one. The next face is where the first node off the base comes down.
    Point away = stands.depth >= 0.0 ? stands.edge - q : q - stands.edge;
    bool either_way = false;
    if (away.norm() <= rounding) {
      away = stands.outward;
      either_way = stands.either_way;
    }
    const double away_length = away.norm();
    landing.next_face_degrees = 180.0;
    for (const Index i : nodes) {
      const double rise = ground_.clearance(i, x[i]) - bottom;
      const Point offset = on_plane(x[i]) - stands.edge;
      double beyond = away_length > 0.0 ? offset.dot(away) / away_length : offset.norm();
      beyond = either_way ? std::abs(beyond) : beyond;
      if (rise > kBaseTolerance * size && beyond >= -rounding) {
        landing.next_face_degrees =
            std::min(landing.next_face_degrees, degrees(std::atan2(rise, std::max(beyond, 0.0))));
      }
    }
    return landing;
  }

 private:
  static double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

  // x carried along gravity onto the plane, in the plane's axes.
  Point on_plane(const Vec3& x) const {
    const Vec3 landed =
        x - ((x - ground_.point).dot(ground_.normal) / down_.dot(ground_.normal)) * down_;
    return {landed.dot(across_), landed.dot(along_)};
  }

  const Model& model_;
  const GroundContact& ground_;
  Vec3 down_, across_, along_;
  std::vector<Point> base_;
};

}  // namespace

std::vector<PieceLanding> piece_landings(const Model& model, const MeshPieces& pieces) {
  std::vector<PieceLanding> landings;
  const GroundContact& ground = model.ground;
  if (!ground.enabled || model.gravity.dot(ground.normal) >= 0.0) {
    return landings;
  }
  const std::vector<Index> order = nodes_by_piece(pieces);
  Landing landing(model);
  for (std::size_t first = 0; first < order.size();) {
    const Index piece = pieces.piece[order[first]];
    const auto count = static_cast<std::size_t>(pieces.size[piece]);
    if (pieces.held[piece] == 0 && count > 1) {
      landings.push_back(landing.of(std::span<const Index>(order).subspan(first, count)));
    }
    first += count;
  }
  return landings;
}

std::optional<PieceLanding> rocking_landing(const Model& model, const MeshPieces& pieces) {
  std::optional<PieceLanding> readiest;
  for (const PieceLanding& piece : piece_landings(model, pieces)) {
    if (piece.tipping_degrees < kLeastTippingDegrees &&
        piece.next_face_degrees < kRoundBaseDegrees &&
        (!readiest || piece.tipping_degrees < readiest->tipping_degrees)) {
      readiest = piece;
    }
  }
  return readiest;
}

}  // namespace dinam
