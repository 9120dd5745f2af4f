// `cogmap sonar-model --out DIR [--world WORLD] [--range R]`: the simulator's echo model as
// figures and a table (docs/sonar-model.md "The echo model"): for each material, a P2-AT front
// transducer facing a flat wall that crosses its axis at R metres, turned from square (0 deg)
// to grazing, gives the probability of hearing anything and the median reading.
#include <CLI/CLI.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <sstream>

#include "cogmap/mapper/io/asr_json.h"
#include "cogmap/render/figures.h"
#include "cogmap/render/renderer.h"
#include "cogmap/sim/sonar_model.h"
#include "cogmap/sim/world_spec.h"
#include "command_registry.h"
#include "option_checks.h"

namespace cogmap::cli {
namespace {

namespace fs = std::filesystem;
constexpr double kDeg = std::numbers::pi / 180.0;

struct SonarModelArgs {
  std::string out;
  std::string world;
  double range_m = 2.0;
  bool force = false;
};

// What the command writes into --out.
const std::vector<std::string> kOutputFiles{"echo_model.csv", "echo_probability.png",
                                            "echo_range.png"};

// --out, before any work: a folder (or a new one), and none of the three files there unless
// --force, since the folder may be the user's own (an echo_model.csv of theirs was replaced).
void check_out_folder(const SonarModelArgs& args) {
  std::error_code ec;
  if (fs::exists(args.out, ec) && !fs::is_directory(args.out, ec)) {
    throw OutputPathError(args.out + ": not a directory; choose another --out");
  }
  std::vector<fs::path> inputs;
  if (!args.world.empty()) inputs.emplace_back(args.world);
  for (const std::string& name : kOutputFiles) {
    check_output_file(fs::path(args.out) / name, "--out", inputs, args.force);
  }
}

struct Response {
  double probability = 0.0;  // of any echo (before dropouts)
  double median_m = 0.0;     // median reading given an echo (noise-free), 0 when none
};

// The distribution of the first heard candidate, from the candidates alone: candidate k is the
// reading with probability p_k * prod_{j<k} (1 - p_j), read threshold_walk_m * (1 - p_k) long.
Response response(const std::vector<sim::EchoCandidate>& candidates, double walk_m) {
  std::vector<std::pair<double, double>> reading_weight;
  double silent = 1.0;
  for (const sim::EchoCandidate& c : candidates) {
    const double p = -std::expm1(-std::max(c.strength, 0.0));
    reading_weight.emplace_back(c.range_m + walk_m * (1.0 - p), silent * p);
    silent *= 1.0 - p;
  }
  Response r;
  r.probability = 1.0 - silent;
  if (r.probability <= 0.0) return r;
  std::sort(reading_weight.begin(), reading_weight.end());
  double acc = 0.0;
  for (const auto& [range, w] : reading_weight) {
    acc += w;
    if (acc >= 0.5 * r.probability) {
      r.median_m = range;
      break;
    }
  }
  return r;
}

int sonar_model(const SonarModelArgs& args) {
  std::vector<sim::SonarMaterial> materials = sim::builtin_sonar_materials();
  try {
    check_out_folder(args);
    if (!args.world.empty()) materials = sim::load_world(args.world).materials;
  } catch (const std::exception& e) {
    std::cerr << "cogmap sonar-model: " << e.what() << "\n";
    return kExitBadInput;
  }
  try {
    render::require_renderer();  // before any work: the two plots need it
  } catch (const render::RendererUnavailable& e) {
    std::cerr << "cogmap sonar-model: " << e.what() << "\n";
    return kExitBadInput;
  }
  const mapper::RobotGeometry geometry = mapper::p2at_geometry();
  const sim::SonarModelOptions options;
  const sim::SonarModel model(options, geometry, 1);
  constexpr int kIndex = 3;  // front, 10 deg left: the scene is built in its own frame
  const mapper::SonarMount& mount = geometry.sonars[kIndex];
  // Place the robot so the transducer sits at the origin facing +x.
  const mapper::Pose2 transducer_pose(0.0, 0.0, 0.0);
  const mapper::Pose2 robot =
      transducer_pose.compose(mapper::Pose2(mount.x_m, mount.y_m, mount.heading_rad).inverse());

  std::vector<render::PlotSeries> probability, median;
  std::ostringstream csv;
  csv << "material,incidence_deg,echo_probability,median_reading_m\n";
  for (std::size_t m = 0; m < materials.size(); ++m) {
    render::PlotSeries p{materials[m].name, {}, {}, {}}, r{materials[m].name, {}, {}, {}};
    for (int deg = 0; deg <= 85; deg += 5) {
      // The wall crosses the axis at range_m; its normal is turned `deg` from the axis.
      const double a = deg * kDeg;
      const mapper::Point2 hit(args.range_m, 0.0);
      const mapper::Point2 along(-std::sin(a), std::cos(a));
      sim::SonarScene scene;
      scene.surfaces = {{hit - 20.0 * along, hit + 20.0 * along}};
      scene.surface_material = {static_cast<int>(m)};
      scene.materials = materials;
      const Response resp =
          response(model.echo_candidates(scene, robot, kIndex), options.threshold_walk_m);
      p.x.push_back(deg);
      p.y_mean.push_back(resp.probability);
      if (resp.probability >= 0.01) {
        r.x.push_back(deg);
        r.y_mean.push_back(resp.median_m);
      }
      csv << materials[m].name << ',' << deg << ',' << resp.probability << ',' << resp.median_m
          << "\n";
    }
    probability.push_back(p);
    median.push_back(r);
  }
  try {
    fs::create_directories(args.out);
    mapper::io::write_file_atomic(fs::path(args.out) / "echo_model.csv", csv.str());
    std::ostringstream at;
    at << " (wall at " << args.range_m << " m on the axis)";
    render::write_metric_plot("Echo probability" + at.str(), "incidence on the axis (deg)",
                              "P(echo)", probability, fs::path(args.out) / "echo_probability.png");
    render::write_metric_plot("Median reading" + at.str(), "incidence on the axis (deg)",
                              "median reading (m)", median, fs::path(args.out) / "echo_range.png");
  } catch (const std::exception& e) {
    std::cerr << "cogmap sonar-model: " << e.what() << "\n";
    return kExitFailed;
  }
  std::cout << "cogmap sonar-model: " << materials.size() << " materials, outputs in " << args.out
            << "\n";
  return kExitOk;
}

const CommandRegistrar kSonarModelRegistrar{
    "sonar-model", [](CLI::App& app, int& exit_code) {
      auto args = std::make_shared<SonarModelArgs>();
      CLI::App* sub = app.add_subcommand(
          "sonar-model",
          "Figures of the simulated echo model: echo probability and median reading against "
          "incidence, per material");
      sub->add_option("--out", args->out, "output folder")->required();
      sub->add_flag("--force", args->force,
                    "replace echo_model.csv, echo_probability.png and echo_range.png in --out");
      sub->add_option("--world", args->world, "take the materials of this world file")
          ->check(CLI::ExistingFile);
      sub->add_option("--range", args->range_m, "where the wall crosses the axis, m (default 2)")
          ->check(finite_range(0.2, 4.9));
      sub->callback([&exit_code, args] { exit_code = sonar_model(*args); });
    }};

}  // namespace
}  // namespace cogmap::cli
