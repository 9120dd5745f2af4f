// The room graph <-> asr_graph.json (docs/asr-format.md).

#include "cogmap/mapper/io/asr_json.h"
#include "json_reader.h"

namespace cogmap::mapper::io {

std::string asr_graph_to_json_text(const AsrGraph& graph) {
  ojson nodes = ojson::array();
  for (std::size_t i = 0; i < graph.nodes().size(); ++i) {
    const AsrNode& n = graph.nodes()[i];
    const std::string path = JsonReader::index("nodes", i);
    nodes.push_back(
        ojson{{"id", n.id},
              {"pose", pose_json(n.pose, path + ".pose")},
              {"reference_point", point_json(n.reference_point_world, path + ".reference_point")}});
  }
  ojson edges = ojson::array();
  for (std::size_t i = 0; i < graph.edges().size(); ++i) {
    const AsrEdge& e = graph.edges()[i];
    const std::string path = JsonReader::index("edges", i);
    edges.push_back(ojson{{"from", e.from},
                          {"to", e.to},
                          {"exit_index", e.exit_index},
                          {"exit", point_json(e.exit_world, path + ".exit")}});
  }
  const ojson root{
      {"format", kAsrGraphFormat}, {"version", kFormatVersion}, {"nodes", nodes}, {"edges", edges}};
  return root.dump(1) + "\n";
}

AsrGraph asr_graph_from_json_text(std::string_view text, const std::string& file) {
  const JsonReader r(file);
  const json root = r.parse(text);
  r.header(root, kAsrGraphFormat);
  r.expect_object(root, "", {"format", "version", "nodes", "edges"});
  AsrGraph graph;
  const json& nodes = r.array(root["nodes"], "nodes");
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const std::string path = JsonReader::index("nodes", i);
    r.expect_object(nodes[i], path, {"id", "pose", "reference_point"});
    AsrNode n;
    n.id = r.integer(nodes[i]["id"], path + ".id");
    if (graph.node(n.id)) r.fail(path + ".id", "duplicate node id " + std::to_string(n.id));
    n.pose = r.pose(nodes[i]["pose"], path + ".pose");
    n.reference_point_world = r.point(nodes[i]["reference_point"], path + ".reference_point");
    graph.add_node(n);
  }
  const json& edges = r.array(root["edges"], "edges");
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const std::string path = JsonReader::index("edges", i);
    r.expect_object(edges[i], path, {"from", "to", "exit_index", "exit"});
    AsrEdge e;
    e.from = r.integer(edges[i]["from"], path + ".from");
    e.to = r.integer(edges[i]["to"], path + ".to");
    e.exit_index = r.integer(edges[i]["exit_index"], path + ".exit_index");
    e.exit_world = r.point(edges[i]["exit"], path + ".exit");
    if (!graph.node(e.from)) r.fail(path + ".from", "no node with id " + std::to_string(e.from));
    if (!graph.node(e.to)) r.fail(path + ".to", "no node with id " + std::to_string(e.to));
    graph.add_edge(e);
  }
  return graph;
}

void write_asr_graph_json(const AsrGraph& graph, const std::filesystem::path& path,
                          Durability durability) {
  write_file_atomic(path, asr_graph_to_json_text(graph), durability);
}

AsrGraph read_asr_graph_json(const std::filesystem::path& path) {
  return asr_graph_from_json_text(read_file(path), path.string());
}

}  // namespace cogmap::mapper::io
