#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <stdexcept>
#include <string>

#include "cogmap/mapper/io/asr_json.h"
#include "cogmap/mapper/io/directory_asr_store.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::mapper::io {
namespace {

namespace fs = std::filesystem;

/// A fresh, empty directory for one test, removed with the process's scratch.
fs::path fresh_dir(const std::string& name) { return test_support::fresh_scratch(name); }

/// An ASR whose every field holds a value with all 53 bits of mantissa in use.
Asr sample_asr(int id) {
  std::mt19937_64 rng(1000 + id);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  Asr a;
  a.id = id;
  a.pose = {u(rng), u(rng), 0.1 * u(rng)};
  a.odometry_pose = {u(rng), u(rng), 0.1 * u(rng)};
  for (int w = 0; w < 3; ++w) {
    Polyline line;
    for (int v = 0; v < 6; ++v) line.push_back({u(rng), u(rng)});
    a.walls.push_back(line);
  }
  a.exits.push_back({{u(rng), u(rng)}, 0.9123456789012345, 1.0 / 3.0, std::nullopt});
  a.exits.push_back({{u(rng), u(rng)}, 0.0, -2.0 / 7.0, id + 1});
  a.reference_point = {u(rng), u(rng)};
  a.parent = id > 0 ? std::optional<int>(id - 1) : std::nullopt;
  a.heading_correction_rad = -0.1234567890123456789;
  for (int k = 0; k < 5; ++k) a.path.push_back({u(rng), u(rng)});
  a.cell_scale_mm = 55.5;
  a.grid_bytes = 9'876'543'210ull;
  a.extracted_vertex_count = 321;
  a.start_time_s = 12.345678901234567;
  a.end_time_s = 1e-300;  // denormal-adjacent: printing must still round-trip
  return a;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_bit_exact(const Asr& a, const Asr& b) {
  EXPECT_EQ(a.id, b.id);
  for (const auto& [p, q] :
       {std::pair{a.pose, b.pose}, std::pair{a.odometry_pose, b.odometry_pose}}) {
    EXPECT_TRUE(same_bits(p.x_m, q.x_m) && same_bits(p.y_m, q.y_m) &&
                same_bits(p.theta_rad, q.theta_rad));
  }
  ASSERT_EQ(a.walls.size(), b.walls.size());
  for (std::size_t i = 0; i < a.walls.size(); ++i) {
    ASSERT_EQ(a.walls[i].size(), b.walls[i].size());
    for (std::size_t v = 0; v < a.walls[i].size(); ++v) {
      EXPECT_TRUE(same_bits(a.walls[i][v].x(), b.walls[i][v].x()));
      EXPECT_TRUE(same_bits(a.walls[i][v].y(), b.walls[i][v].y()));
    }
  }
  ASSERT_EQ(a.exits.size(), b.exits.size());
  for (std::size_t i = 0; i < a.exits.size(); ++i) {
    EXPECT_TRUE(same_bits(a.exits[i].center.x(), b.exits[i].center.x()));
    EXPECT_TRUE(same_bits(a.exits[i].center.y(), b.exits[i].center.y()));
    EXPECT_TRUE(same_bits(a.exits[i].width_m, b.exits[i].width_m));
    EXPECT_TRUE(same_bits(a.exits[i].heading_rad, b.exits[i].heading_rad));
    EXPECT_EQ(a.exits[i].neighbour, b.exits[i].neighbour);
  }
  EXPECT_TRUE(same_bits(a.reference_point.x(), b.reference_point.x()));
  EXPECT_TRUE(same_bits(a.reference_point.y(), b.reference_point.y()));
  EXPECT_EQ(a.parent, b.parent);
  EXPECT_TRUE(same_bits(a.heading_correction_rad, b.heading_correction_rad));
  ASSERT_EQ(a.path.size(), b.path.size());
  for (std::size_t i = 0; i < a.path.size(); ++i) {
    EXPECT_TRUE(same_bits(a.path[i].x(), b.path[i].x()));
    EXPECT_TRUE(same_bits(a.path[i].y(), b.path[i].y()));
  }
  EXPECT_TRUE(same_bits(a.cell_scale_mm, b.cell_scale_mm));
  EXPECT_EQ(a.grid_bytes, b.grid_bytes);
  EXPECT_EQ(a.extracted_vertex_count, b.extracted_vertex_count);
  EXPECT_TRUE(same_bits(a.start_time_s, b.start_time_s));
  EXPECT_TRUE(same_bits(a.end_time_s, b.end_time_s));
}

/// The message of the runtime_error `text` raises when read as "asrs/003.json".
std::string load_error(const std::string& text) {
  try {
    asr_from_json_text(text, "asrs/003.json");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(no error)";
}

/// A valid file with one substring replaced.
std::string edited(const std::string& from, const std::string& to) {
  std::string text = asr_to_json_text(sample_asr(3));
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(AsrJson, RoundTripIsBitExact) {
  for (int id : {0, 3, 42}) {
    const Asr a = sample_asr(id);
    expect_bit_exact(a, asr_from_json_text(asr_to_json_text(a), "mem"));
  }
}

TEST(AsrJson, HeaderComesFirst) {
  const std::string text = asr_to_json_text(sample_asr(1));
  EXPECT_LT(text.find("\"format\": \"cogmap-asr\""), text.find("\"id\""));
  EXPECT_LT(text.find("\"version\": 1"), text.find("\"id\""));
}

TEST(AsrJson, TruncatedFileNamesTheByte) {
  const std::string text = asr_to_json_text(sample_asr(3));
  const std::string msg = load_error(text.substr(0, 100));
  EXPECT_EQ(msg, "asrs/003.json: not valid JSON at byte 101") << msg;
}

TEST(AsrJson, GarbageByteNamesTheByte) {
  std::string text = asr_to_json_text(sample_asr(3));
  text[40] = '\x01';
  EXPECT_EQ(load_error(text), "asrs/003.json: not valid JSON at byte 41");
}

TEST(AsrJson, WrongTypesNameTheField) {
  // A wall vertex that is not a pair of numbers.
  std::string text = asr_to_json_text(sample_asr(3));
  {
    nlohmann::json j = nlohmann::json::parse(text);
    j["walls"][2][5] = "oops";
    EXPECT_EQ(load_error(j.dump()), "asrs/003.json: walls[2][5]: expected [x, y] numbers");
    j["walls"][2][5] = {1.0, 2.0, 3.0};
    EXPECT_EQ(load_error(j.dump()), "asrs/003.json: walls[2][5]: expected [x, y] numbers");
  }
  nlohmann::json j = nlohmann::json::parse(text);
  j["pose"]["theta_rad"] = "north";
  EXPECT_EQ(load_error(j.dump()), "asrs/003.json: pose.theta_rad: expected a number");
  j = nlohmann::json::parse(text);
  j["exits"][1]["neighbour"] = 1.5;
  EXPECT_EQ(load_error(j.dump()), "asrs/003.json: exits[1].neighbour: expected an integer or null");
  j = nlohmann::json::parse(text);
  j["grid_bytes"] = -4;
  EXPECT_EQ(load_error(j.dump()), "asrs/003.json: grid_bytes: expected a non-negative integer");
  j = nlohmann::json::parse(text);
  j["walls"] = nlohmann::json::object();
  EXPECT_EQ(load_error(j.dump()), "asrs/003.json: walls: expected an array");
}

TEST(AsrJson, NonFiniteNumbersAreRejected) {
  // JSON has no NaN, and a number too large for a double is refused by the parser.
  EXPECT_EQ(load_error(edited("\"start_time_s\": 12.345678901234567", "\"start_time_s\": 1e999")),
            "asrs/003.json: not valid JSON: a number is too large for a double");
  Asr a = sample_asr(3);
  a.walls[1][2].x() = std::nan("");
  EXPECT_THROW(asr_to_json_text(a), std::invalid_argument);
}

TEST(AsrJson, MissingAndUnknownFieldsNameTheField) {
  nlohmann::json j = nlohmann::json::parse(asr_to_json_text(sample_asr(3)));
  j.erase("reference_point");
  EXPECT_EQ(load_error(j.dump()), "asrs/003.json: reference_point: missing required field");
  j = nlohmann::json::parse(asr_to_json_text(sample_asr(3)));
  j["exits"][0].erase("width_m");
  EXPECT_EQ(load_error(j.dump()), "asrs/003.json: exits[0].width_m: missing required field");
  j = nlohmann::json::parse(asr_to_json_text(sample_asr(3)));
  j["colour"] = "red";
  EXPECT_EQ(load_error(j.dump()), "asrs/003.json: colour: unknown field");
}

TEST(AsrJson, WrongVersionOrFormatIsRejected) {
  EXPECT_EQ(load_error(edited("\"version\": 1", "\"version\": 2")),
            "asrs/003.json: version: unsupported version 2 (this reader knows 1)");
  EXPECT_EQ(load_error(edited("\"format\": \"cogmap-asr\"", "\"format\": \"other\"")),
            "asrs/003.json: format: expected \"cogmap-asr\"");
  EXPECT_EQ(load_error("[1, 2]"), "asrs/003.json: (root): expected an object");
}

TEST(DirectoryAsrStore, SavesLoadsAndListsSortedIds) {
  const fs::path dir = fresh_dir("store");
  {
    DirectoryAsrStore store(dir);
    for (int id : {7, 0, 3, 12}) store.save(sample_asr(id));
    EXPECT_EQ(store.ids(), (std::vector<int>{0, 3, 7, 12}));
    EXPECT_TRUE(fs::exists(dir / "003.json"));
    EXPECT_TRUE(fs::exists(dir / "012.json"));
    expect_bit_exact(sample_asr(7), store.load(7));
  }
  // A new store over the same directory rebuilds its index from the file names only.
  std::ofstream(dir / "notes.txt") << "not a room";
  std::ofstream(dir / "0003.json") << "{}";
  DirectoryAsrStore reopened(dir);
  EXPECT_EQ(reopened.ids(), (std::vector<int>{0, 3, 7, 12}));
  expect_bit_exact(sample_asr(12), reopened.load(12));
  // No temp files are left behind.
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  }
}

TEST(DirectoryAsrStore, SavingTwiceReplaces) {
  DirectoryAsrStore store(fresh_dir("replace"));
  Asr a = sample_asr(5);
  store.save(a);
  a.heading_correction_rad = 0.25;
  a.walls.pop_back();
  store.save(a);
  EXPECT_EQ(store.ids(), (std::vector<int>{5}));
  expect_bit_exact(a, store.load(5));
}

TEST(DirectoryAsrStore, CorruptFileNamesFileAndByte) {
  const fs::path dir = fresh_dir("corrupt");
  DirectoryAsrStore store(dir);
  store.save(sample_asr(3));
  const std::string text = read_file(dir / "003.json");
  std::ofstream(dir / "003.json", std::ios::trunc) << text.substr(0, 57);
  try {
    store.load(3);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "003.json").string() + ": not valid JSON at byte 58");
  }
}

TEST(DirectoryAsrStore, IdMustMatchTheFileName) {
  const fs::path dir = fresh_dir("mismatch");
  write_file_atomic(dir / "004.json", asr_to_json_text(sample_asr(9)));
  DirectoryAsrStore store(dir);
  EXPECT_EQ(store.ids(), (std::vector<int>{4}));
  EXPECT_THROW(store.load(4), std::runtime_error);
  EXPECT_THROW(store.load(5), std::runtime_error);  // no such file
  EXPECT_THROW(store.save(sample_asr(-1)), std::invalid_argument);
}

TEST(AtomicWrite, LeftoverTempFromACrashDoesNotTouchTheOldFile) {
  // A crash between "write temp" and "rename" leaves a temp file and the intact old file; the
  // store ignores the temp and keeps serving the old room.
  const fs::path dir = fresh_dir("crash");
  DirectoryAsrStore store(dir);
  store.save(sample_asr(1));
  std::ofstream(dir / ".001.json.tmp-99999-0") << "{\"format\": \"cogmap-as";
  DirectoryAsrStore reopened(dir);
  EXPECT_EQ(reopened.ids(), (std::vector<int>{1}));
  expect_bit_exact(sample_asr(1), reopened.load(1));
}

TEST(AtomicWrite, UnsyncedStoreStillReplacesWholeFilesAndLeavesNoTemp) {
  // Durability::kAtomic drops only the fsyncs: the rooms read back bit for bit, a second save
  // replaces the first, and no temporary file is left behind.
  const fs::path dir = fresh_dir("unsynced");
  DirectoryAsrStore store(dir, Durability::kAtomic);
  store.save(sample_asr(1));
  store.save(sample_asr(1));
  store.save(sample_asr(2));
  EXPECT_EQ(store.ids(), (std::vector<int>{1, 2}));
  expect_bit_exact(sample_asr(2), DirectoryAsrStore(dir).load(2));
  write_file_atomic(dir / "note.txt", "first", Durability::kAtomic);
  write_file_atomic(dir / "note.txt", "second", Durability::kAtomic);
  EXPECT_EQ(read_file(dir / "note.txt"), "second");
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_FALSE(is_temp_file_name(e.path().filename().string())) << e.path();
  }
}

TEST(AtomicWrite, ChunksAreWrittenInOrderAndAFailingProducerLeavesTheOldFile) {
  const fs::path dir = fresh_dir("chunks");
  write_file_atomic_chunks(dir / "t.csv", [](const ChunkSink& emit) {
    emit("a,b\n");
    emit("");
    emit("1,2\n");
  });
  EXPECT_EQ(read_file(dir / "t.csv"), "a,b\n1,2\n");
  EXPECT_THROW(write_file_atomic_chunks(dir / "t.csv",
                                        [](const ChunkSink& emit) {
                                          emit("half a file");
                                          throw std::runtime_error("producer failed");
                                        }),
               std::runtime_error);
  EXPECT_EQ(read_file(dir / "t.csv"), "a,b\n1,2\n");  // untouched
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_FALSE(is_temp_file_name(e.path().filename().string())) << e.path();
  }
}

TEST(AsrGraphJson, RoundTripAndValidation) {
  AsrGraph g;
  g.add_node({0, {0.1, 0.2, 0.3}, {1.0 / 3.0, 2.0}});
  g.add_node({1, {5.0, -1.0, -0.7}, {6.0, 1e-17}});
  g.add_edge({0, 1, 1, {4.5, 0.25}});
  const fs::path path = fresh_dir("graph") / "asr_graph.json";
  write_asr_graph_json(g, path);
  const AsrGraph back = read_asr_graph_json(path);
  ASSERT_EQ(back.nodes().size(), 2u);
  ASSERT_EQ(back.edges().size(), 1u);
  EXPECT_TRUE(same_bits(back.nodes()[0].reference_point_world.x(), 1.0 / 3.0));
  EXPECT_TRUE(same_bits(back.nodes()[1].pose.theta_rad, -0.7));
  EXPECT_EQ(back.edges()[0].exit_index, 1);
  EXPECT_TRUE(same_bits(back.edges()[0].exit_world.y(), 0.25));
  EXPECT_EQ(back.neighbours(0), (std::vector<int>{1}));

  nlohmann::json j = nlohmann::json::parse(read_file(path));
  j["edges"][0]["to"] = 9;
  try {
    asr_graph_from_json_text(j.dump(), "asr_graph.json");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "asr_graph.json: edges[0].to: no node with id 9");
  }
}

}  // namespace
}  // namespace cogmap::mapper::io
