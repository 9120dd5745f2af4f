// Relaxing the rooms' positions at the end of a run (docs/algorithms.md, "Relaxing the rooms'
// positions at the end of a run"): the rooms' shifts and one wall thickness as the unknowns of
// a sparse least-squares problem. Rows: room 0 stays; consecutive rooms keep their offset
// within the drift of the path between them; each pair of wall pieces that are the same wall
// seen from the same side (offset 0; or the next run of its line, measured at the nearer end)
// or the two faces of one wall (offset = the thickness) says
// normal · (s_i − s_j) [+ thickness] = the offset measured.

#include "cogmap/mapper/localization/map_relaxation.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace cogmap::mapper {
namespace {

/// One wall pair: normal · (s_i − s_j) [+ t when two_face] = offset_m.
struct PairRow {
  int i = 0, j = 0;
  Point2 normal{0.0, 0.0};
  double offset_m = 0.0;    ///< as measured with both rooms unshifted
  double residual_m = 0.0;  ///< left with the rooms where they stand now (thickness included)
  double overlap_m = 0.0;
  double extrapolated_m = 0.0;  ///< how far past the earlier piece's end the offset was taken
  bool two_face = false;
};

struct Box {
  Point2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Point2 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  bool empty() const { return !(lo.x() <= hi.x()); }
};

Box bounds(const RelaxationRoom& room) {
  Box b;
  for (const FacingSegment& w : room.walls) {
    b.lo = b.lo.cwiseMin(w.a).cwiseMin(w.b);
    b.hi = b.hi.cwiseMax(w.a).cwiseMax(w.b);
  }
  return b;
}

bool finite(const FacingSegment& w) {
  return w.a.allFinite() && w.b.allFinite() && w.normal.allFinite() && (w.b - w.a).norm() > 0.0;
}

/// The partner of each of room i's pieces among room j's (rooms shifted by si, sj), within
/// `gate`: the nearest along the normal, unless the next is nearly as near.
void pair_rooms(int i, int j, const RelaxationRoom& ri, const RelaxationRoom& rj, const Point2& si,
                const Point2& sj, double gate, double thickness_m, const RelaxationOptions& o,
                std::vector<PairRow>& out) {
  const double sin_max = std::sin(o.max_angle_deg * std::numbers::pi / 180.0);
  std::vector<PairRow> candidates;
  for (const FacingSegment& c : ri.walls) {
    const Point2 ca = c.a + si, cb = c.b + si;
    const Point2 uc = (cb - ca).normalized();
    // Every candidate within the gate; the nearest wins unless another lies at a clearly
    // different offset nearly as near (pieces of one wall split by a gap agree: no doubt).
    candidates.clear();
    for (const FacingSegment& r : rj.walls) {
      const bool same_side = c.normal.dot(r.normal) > 0.0;
      const Point2 ra = r.a + sj, rb = r.b + sj;
      const double r_len = (rb - ra).norm();
      const Point2 ur = (rb - ra) / r_len;
      if (std::abs(cross(uc, ur)) > sin_max) continue;
      const double s0 = ur.dot(ca - ra), s1 = ur.dot(cb - ra);
      const double lo = std::max(std::min(s0, s1), 0.0), hi = std::min(std::max(s0, s1), r_len);
      double overlap = hi - lo;
      if (s1 == s0) continue;
      double at = 0.5 * (lo + hi);  // where along r the offset is taken
      if (overlap < o.min_overlap_m) {
        // Collinear pieces of one wall line that do not overlap (consecutive cuts of a corridor,
        // a wall's run on either side of a junction or along a corridor): the offset at c's end
        // nearest to r, to r's line, weighed as continuation_weight_m of overlap and less the
        // farther past r's end it lies (continuation_angle_sd_rad).
        if (!(o.continuation_gap_m > 0.0) || !same_side || overlap < -o.continuation_gap_m)
          continue;
        const double c_lo = std::min(s0, s1), c_hi = std::max(s0, s1);
        at = c_lo >= r_len ? c_lo : (c_hi <= 0.0 ? c_hi : 0.5 * (lo + hi));
        overlap = o.continuation_weight_m;
      }
      const double extrapolated = at > r_len ? at - r_len : (at < 0.0 ? -at : 0.0);
      const Point2 p = ca + (at - s0) / (s1 - s0) * (cb - ca);
      // Along r's normal (towards where r was seen from): 0 for the same face, −thickness for
      // the face on the wall's other side.
      const double offset = r.normal.dot(ra - p);
      const double residual = same_side ? offset : offset - thickness_m;
      if (std::abs(residual) > gate) continue;
      // Measured as if both rooms stood unshifted: the rows are linear in the shifts.
      candidates.push_back({i, j, r.normal, offset + r.normal.dot(si - sj), residual, overlap,
                            extrapolated, !same_side});
    }
    if (candidates.empty()) continue;
    const auto best = std::min_element(candidates.begin(), candidates.end(),
                                       [](const PairRow& a, const PairRow& b) {
                                         return std::abs(a.residual_m) < std::abs(b.residual_m);
                                       });
    const double best_abs = std::abs(best->residual_m);
    const bool ambiguous = std::any_of(candidates.begin(), candidates.end(), [&](const PairRow& x) {
      return std::abs(x.residual_m - best->residual_m) > o.ambiguity_margin_m &&
             std::abs(x.residual_m) < o.ambiguity_ratio * best_abs + o.ambiguity_margin_m;
    });
    if (ambiguous) continue;
    out.push_back(*best);
  }
}

}  // namespace

Relaxation relax_room_positions(std::span<const RelaxationRoom> input, const RelaxationOptions& o) {
  const int n = static_cast<int>(input.size());
  Relaxation result;
  result.shifts.assign(input.size(), Point2::Zero());
  result.wall_thickness_m = o.wall_thickness_m;
  if (n < 2) return result;

  // Pieces with a non-finite or empty geometry are left out; a non-finite path counts as none.
  std::vector<RelaxationRoom> rooms(input.begin(), input.end());
  for (RelaxationRoom& room : rooms) {
    std::erase_if(room.walls, [](const FacingSegment& w) { return !finite(w); });
    if (!std::isfinite(room.path_m) || room.path_m < 0.0) room.path_m = 0.0;
  }
  // Variance of the drift between room 0 and room k, summed along the chain.
  std::vector<double> step_var(n, 0.0), chain_var(n, 0.0);
  for (int k = 1; k < n; ++k) {
    const double sd = std::max(o.drift_sd_per_m * rooms[k].path_m, o.min_step_sd_m);
    step_var[k] = sd * sd;
    chain_var[k] = chain_var[k - 1] + step_var[k];
  }
  std::vector<Box> boxes;
  for (const RelaxationRoom& room : rooms) boxes.push_back(bounds(room));
  // Each room's candidate partners: the earlier rooms whose walls come near its own, the
  // max_partners nearest (a robot that tours one office for hours cuts thousands of rooms in
  // the same place; every pair of them would make the search quadratic and the problem dense).
  const double reach_m = o.max_gate_m + o.wall_thickness_m + o.continuation_gap_m + 1.0;
  std::vector<std::vector<int>> partners(n);
  for (int i = 1; i < n; ++i) {
    if (boxes[i].empty()) continue;
    const Point2 centre_i = 0.5 * (boxes[i].lo + boxes[i].hi);
    std::vector<std::pair<double, int>> near;
    for (int j = 0; j < i; ++j) {
      if (boxes[j].empty()) continue;
      if ((boxes[i].lo.array() > boxes[j].hi.array() + reach_m).any() ||
          (boxes[j].lo.array() > boxes[i].hi.array() + reach_m).any()) {
        continue;
      }
      near.emplace_back((0.5 * (boxes[j].lo + boxes[j].hi) - centre_i).squaredNorm(), j);
    }
    const std::size_t keep = std::min<std::size_t>(near.size(), std::max(o.max_partners, 0));
    std::partial_sort(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(keep), near.end());
    for (std::size_t k = 0; k < keep; ++k) partners[i].push_back(near[k].second);
  }

  const int unknowns = 2 * n + 1;  // the shifts, then the thickness
  const int t_index = 2 * n;
  double thickness = o.wall_thickness_m;
  const double pair_var_same = o.offset_sd_m * o.offset_sd_m;
  const double pair_var_two = pair_var_same + o.wall_thickness_sd_m * o.wall_thickness_sd_m;
  std::vector<PairRow> pairs;
  for (int round = 0; round < std::max(o.rounds, 1); ++round) {
    pairs.clear();
    for (int i = 1; i < n; ++i) {
      for (const int j : partners[i]) {
        const double first_gate = std::clamp(o.gate_sigmas * std::sqrt(chain_var[i] - chain_var[j]),
                                             o.min_gate_m, o.max_gate_m);
        const double gate = round == 0 ? first_gate : std::min(first_gate, o.later_gate_m);
        const Point2 si = result.shifts[i], sj = result.shifts[j];
        const Point2 lo_i = boxes[i].lo + si, hi_i = boxes[i].hi + si;
        const Point2 lo_j = boxes[j].lo + sj, hi_j = boxes[j].hi + sj;
        const double margin = gate + o.wall_thickness_m + o.continuation_gap_m;
        if ((lo_i.array() > hi_j.array() + margin).any() ||
            (lo_j.array() > hi_i.array() + margin).any()) {
          continue;
        }
        pair_rooms(i, j, rooms[i], rooms[j], si, sj, gate, thickness, o, pairs);
      }
    }
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
    auto add_row = [&](const std::vector<std::pair<int, double>>& row, double value, double w) {
      for (const auto& [a, ja] : row) {
        rhs[a] += w * ja * value;
        for (const auto& [b, jb] : row) triplets.emplace_back(a, b, w * ja * jb);
      }
    };
    // Room 0 is where the start pose put it.
    add_row({{0, 1.0}}, 0.0, 1e8);
    add_row({{1, 1.0}}, 0.0, 1e8);
    add_row({{t_index, 1.0}}, o.wall_thickness_m,
            1.0 / (o.wall_thickness_sd_m * o.wall_thickness_sd_m));
    for (int k = 1; k < n; ++k) {
      for (int axis = 0; axis < 2; ++axis) {
        add_row({{2 * k + axis, 1.0}, {2 * (k - 1) + axis, -1.0}}, 0.0, 1.0 / step_var[k]);
      }
    }
    for (const PairRow& p : pairs) {
      // An offset taken past the earlier piece's end carries both pieces' turn.
      const double spread = p.extrapolated_m * o.continuation_angle_sd_rad;
      const double var = (p.two_face ? pair_var_two : pair_var_same) + spread * spread;
      double w = p.overlap_m / var;
      const double sd = std::sqrt(var);
      if (round > 0 && std::abs(p.residual_m) > 2.0 * sd) w *= 2.0 * sd / std::abs(p.residual_m);
      std::vector<std::pair<int, double>> row = {{2 * p.i, p.normal.x()},
                                                 {2 * p.i + 1, p.normal.y()},
                                                 {2 * p.j, -p.normal.x()},
                                                 {2 * p.j + 1, -p.normal.y()}};
      if (p.two_face) row.emplace_back(t_index, 1.0);
      add_row(row, p.offset_m, w);
    }
    Eigen::SparseMatrix<double> normal(unknowns, unknowns);
    normal.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
    if (solver.info() != Eigen::Success) break;
    const Eigen::VectorXd x = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !x.allFinite()) break;
    for (int k = 0; k < n; ++k) result.shifts[k] = Point2(x[2 * k], x[2 * k + 1]);
    thickness = x[t_index];
  }
  result.wall_thickness_m = thickness;
  for (const PairRow& p : pairs) ++(p.two_face ? result.two_face_pairs : result.same_side_pairs);
  return result;
}

}  // namespace cogmap::mapper
