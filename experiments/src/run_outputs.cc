#include "cogmap/experiments/run_outputs.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

#include "cogmap/experiments/number_format.h"

namespace cogmap::experiments {
namespace {

using mapper::Point2;

std::string f(double v) { return format_double(v); }

/// ",v1,v2,..." appended in place.
void append_fields(std::string& out, std::initializer_list<double> values) {
  for (const double v : values) {
    out += ',';
    append_double(out, v);
  }
}

// SVG numbers are rounded to 0.1 mm: plenty for a figure, and it keeps the file small.
std::string svg_num(double v) {
  const double r = std::round(v * 10000.0) / 10000.0;
  return format_double(r == 0.0 ? 0.0 : r);
}

/// `header`, then `append_row(out, row)` for each row, handed to `emit` every `rows_per_chunk`
/// rows (and at the end).
template <typename Rows, typename AppendRow>
void csv_chunks(std::string header, const Rows& rows, const AppendRow& append_row,
                const std::function<void(std::string_view)>& emit, std::size_t rows_per_chunk) {
  std::string out = std::move(header);
  std::size_t in_chunk = 0;
  for (const auto& r : rows) {
    append_row(out, r);
    if (++in_chunk >= std::max<std::size_t>(rows_per_chunk, 1)) {
      emit(out);
      out.clear();
      in_chunk = 0;
    }
  }
  if (!out.empty()) emit(out);
}

}  // namespace

void trajectory_csv_chunks(TrajectoryView rows, const std::function<void(std::string_view)>& emit,
                           std::size_t rows_per_chunk) {
  const auto append = [](std::string& out, const TrajectoryRow& r) {
    append_double(out, r.t_s);
    if (r.truth) {
      append_fields(out, {r.truth->x_m, r.truth->y_m, r.truth->theta_rad});
    } else {
      out += ",,,";
    }
    append_fields(out, {r.odometry.x_m, r.odometry.y_m, r.odometry.theta_rad, r.estimate.x_m,
                        r.estimate.y_m, r.estimate.theta_rad});
    out += '\n';
  };
  csv_chunks(
      "t_s,true_x_m,true_y_m,true_theta_rad,odom_x_m,odom_y_m,odom_theta_rad,est_x_m,est_y_m,"
      "est_theta_rad\n",
      rows, append, emit, rows_per_chunk);
}

void nav_trace_csv_chunks(std::span<const NavTraceRow> rows,
                          const std::function<void(std::string_view)>& emit,
                          std::size_t rows_per_chunk) {
  const auto append = [](std::string& out, const NavTraceRow& r) {
    out += f(r.t_s) + "," + r.mode + "," + std::to_string(r.waypoint_index) + "," +
           f(r.target_rad) + ",";
    if (r.has_direction) out += f(r.direction_rad);
    out += r.has_direction ? ",1," : ",0,";
    if (std::isfinite(r.front_clearance_m)) out += f(r.front_clearance_m);
    if (r.door_active) {
      out += ",1," + f(r.door_center_m.x()) + "," + f(r.door_center_m.y()) + "," +
             f(r.door_normal_rad) + "," + f(r.door_width_m);
    } else {
      out += ",0,,,,";
    }
    out += "," + f(r.v_mps) + "," + f(r.w_radps) + '\n';
  };
  csv_chunks(
      "t_s,mode,waypoint_index,target_rad,direction_rad,has_direction,front_clearance_m,"
      "door_active,door_x_m,door_y_m,door_normal_rad,door_width_m,v_mps,w_radps\n",
      rows, append, emit, rows_per_chunk);
}

std::string trajectory_csv(TrajectoryView rows) {
  std::string out;
  trajectory_csv_chunks(rows, [&](std::string_view piece) { out += piece; });
  return out;
}

std::string segments_csv(std::span<const mapper::Mapper::MapSegment> segments) {
  std::string out = "asr_id,x1_m,y1_m,x2_m,y2_m\n";
  for (const auto& s : segments) {
    out += std::to_string(s.asr_id);
    append_fields(out, {s.segment.a.x(), s.segment.a.y(), s.segment.b.x(), s.segment.b.y()});
    out += '\n';
  }
  return out;
}

void move_rooms(std::span<const std::pair<int, mapper::Pose2>> moves,
                std::vector<mapper::Mapper::MapSegment>& map,
                std::vector<std::pair<int, mapper::Point2>>& labels) {
  for (const auto& [id, move] : moves) {
    for (mapper::Mapper::MapSegment& s : map) {
      if (s.asr_id == id) s.segment = {move.transform(s.segment.a), move.transform(s.segment.b)};
    }
    for (auto& [label_id, p] : labels) {
      if (label_id == id) p = move.transform(p);
    }
  }
}

std::vector<mapper::Segment> segments_of(std::span<const mapper::Mapper::MapSegment> map) {
  std::vector<mapper::Segment> out;
  out.reserve(map.size());
  for (const auto& s : map) out.push_back(s.segment);
  return out;
}

std::string map_svg(const SvgMap& m) {
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x;
  double max_x = -min_x, max_y = -min_x;
  auto grow = [&](const Point2& p) {
    min_x = std::min(min_x, p.x());
    max_x = std::max(max_x, p.x());
    min_y = std::min(min_y, p.y());
    max_y = std::max(max_y, p.y());
  };
  for (const auto& s : m.map) grow(s.segment.a), grow(s.segment.b);
  for (const auto& s : m.truth) grow(s.a), grow(s.b);
  for (const auto& p : m.path) grow(p);
  if (!(min_x <= max_x)) min_x = min_y = 0.0, max_x = max_y = 1.0;
  const double margin = 0.5;
  const double bar_band = 0.8;  // room under the map for the scale bar
  min_x -= margin;
  max_x += margin;
  min_y -= margin + bar_band;
  max_y += margin;
  const double w = max_x - min_x, h = max_y - min_y;
  // World -> SVG user units (metres): x unchanged, y flipped so +y (north) points up.
  auto X = [&](double x) { return svg_num(x - min_x); };
  auto Y = [&](double y) { return svg_num(max_y - y); };
  const double px_per_m = std::clamp(1200.0 / std::max(w, h), 10.0, 100.0);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + svg_num(w * px_per_m) +
         "\" height=\"" + svg_num(h * px_per_m) + "\" viewBox=\"0 0 " + svg_num(w) + " " +
         svg_num(h) + "\">\n";
  out += "<title>cogmap merged map (world frame, metres)</title>\n";
  out += "<rect x=\"0\" y=\"0\" width=\"" + svg_num(w) + "\" height=\"" + svg_num(h) +
         "\" fill=\"white\"/>\n";
  auto line = [&](const Point2& a, const Point2& b) {
    return "<line x1=\"" + X(a.x()) + "\" y1=\"" + Y(a.y()) + "\" x2=\"" + X(b.x()) + "\" y2=\"" +
           Y(b.y()) + "\"/>\n";
  };
  if (!m.truth.empty()) {
    out += "<g id=\"truth\" stroke=\"#cccccc\" stroke-width=\"0.08\" stroke-linecap=\"round\">\n";
    for (const auto& s : m.truth) out += line(s.a, s.b);
    out += "</g>\n";
  }
  if (m.path.size() >= 2) {
    out += "<polyline id=\"path\" fill=\"none\" stroke=\"#2f5af2\" stroke-width=\"0.02\" points=\"";
    for (std::size_t i = 0; i < m.path.size(); ++i) {
      out += (i ? " " : "") + X(m.path[i].x()) + "," + Y(m.path[i].y());
    }
    out += "\"/>\n";
  }
  out += "<g id=\"map\" stroke=\"black\" stroke-width=\"0.04\" stroke-linecap=\"round\">\n";
  for (const auto& s : m.map) out += line(s.segment.a, s.segment.b);
  out += "</g>\n";
  if (!m.labels.empty()) {
    out +=
        "<g id=\"rooms\" font-family=\"sans-serif\" font-size=\"0.35\" fill=\"#b02020\" "
        "text-anchor=\"middle\">\n";
    for (const auto& [id, p] : m.labels) {
      out +=
          "<text x=\"" + X(p.x()) + "\" y=\"" + Y(p.y()) + "\">" + std::to_string(id) + "</text>\n";
    }
    out += "</g>\n";
  }
  // Scale bar: the largest of 1, 2, 5, 10, 20 m that fits in a quarter of the width.
  double bar = 1.0;
  for (const double b : {2.0, 5.0, 10.0, 20.0, 50.0}) {
    if (b <= w / 4.0) bar = b;
  }
  const double bx = margin, by = h - margin;
  out += "<g id=\"scale\" stroke=\"black\" stroke-width=\"0.05\">\n";
  out += "<line x1=\"" + svg_num(bx) + "\" y1=\"" + svg_num(by) + "\" x2=\"" + svg_num(bx + bar) +
         "\" y2=\"" + svg_num(by) + "\"/>\n";
  out += "<line x1=\"" + svg_num(bx) + "\" y1=\"" + svg_num(by - 0.15) + "\" x2=\"" + svg_num(bx) +
         "\" y2=\"" + svg_num(by + 0.15) + "\"/>\n";
  out += "<line x1=\"" + svg_num(bx + bar) + "\" y1=\"" + svg_num(by - 0.15) + "\" x2=\"" +
         svg_num(bx + bar) + "\" y2=\"" + svg_num(by + 0.15) + "\"/>\n";
  out += "</g>\n";
  out += "<text x=\"" + svg_num(bx + bar + 0.2) + "\" y=\"" + svg_num(by + 0.12) +
         "\" font-family=\"sans-serif\" font-size=\"0.35\">" + format_double(bar) + " m</text>\n";
  out += "</svg>\n";
  return out;
}

}  // namespace cogmap::experiments
