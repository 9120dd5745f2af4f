"""Reading scripts/gen-building's own output without a YAML library, for the test scripts beside
this file: a world's wall polylines (one JSON list a line) and description, an experiment's
waypoints and duration_s."""
import json
import re


def read_world(path):
    """{"polylines": [...], "description": "..."} of a generated world file."""
    world = {"polylines": [], "description": ""}
    with open(path) as f:
        for line in f:
            if line.startswith("    - [["):
                world["polylines"].append(json.loads(line.strip()[2:]))
            elif line.startswith("description: "):
                world["description"] = line[len("description: "):].strip()
    return world


def _field(path, key):
    with open(path) as f:
        m = re.search(rf"^\s*{key}: (.*)$", f.read(), re.M)
    return m[1] if m else None


def waypoints_of(path):
    """A route experiment's waypoints ([] without any)."""
    text = _field(path, "waypoints")
    return json.loads(text) if text else []


def duration_of(path):
    """An experiment's duration_s (None without one)."""
    text = _field(path, "duration_s")
    return float(text) if text else None
