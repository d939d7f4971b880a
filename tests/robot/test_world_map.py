"""The SDK's solid world (rockly_desktop/robot/sim/world_map.py): data in, clearance, swept motion, laser rays."""
import math

import pytest

from rockly_desktop.robot.sim.world_map import World, load_world
from rockly_desktop.sdk import Texts
from rockly_desktop.sdk import World as SdkWorld
from rockly_desktop.sdk import load_world as sdk_load_world

ROOM_YAML = """\
radius: 0.2
area: [0, 0, 4, 3]
obstacles:
  - {id: wall, kind: wall, name: the_wall, rect: [4, 0, 4.1, 3]}
  - {id: table, name: the_table, rect: [1, 1, 2, 2]}
  - {id: pot, name: the_pot, circle: [3, 2.5, 0.2]}
  - {id: wedge, name: the wedge, polygon: [[0, 2], [0.5, 3], [0, 3]]}
"""
NAMES = {"the_wall": ("the wall", "die Wand"), "the_table": ("the table", "den Tisch"),
         "the_pot": ("the pot", "den Topf")}


def write_catalogue(folder, names):
    """A profile's catalogue (messages.pot, de.po) with these keys: (English, German)."""
    folder.mkdir()
    for name, column in (("messages.pot", None), ("de.po", 1)):
        entries = [f'msgctxt "{key}"\nmsgid "{texts[0]}"\nmsgstr "{texts[column] if column else ""}"\n'
                   for key, texts in names.items()]
        (folder / name).write_text("\n".join(entries), encoding="utf-8")
    return Texts(folder)


@pytest.fixture
def room(tmp_path):
    path = tmp_path / "world.yaml"
    path.write_text(ROOM_YAML, encoding="utf-8")
    return load_world(path, write_catalogue(tmp_path / "locale", NAMES))


def test_the_sdk_offers_the_world():
    assert (SdkWorld, sdk_load_world) == (World, load_world)


def test_a_world_file_names_its_obstacles_from_the_profiles_catalogue_in_every_language(room):
    assert [o.id for o in room.obstacles] == ["wall", "table", "pot", "wedge"]
    table = room.obstacle("table")
    assert (table.name("en"), table.name("de"), table.name("fr"), table.kind) == ("the table", "den Tisch",
                                                                                   "the table", "furniture")
    assert room.obstacle("wedge").name("de") == "the wedge"     # not a key: shown as it is
    assert table.bounds == (1.0, 1.0, 2.0, 2.0)
    assert room.radius == 0.2 and room.area == (0.0, 0.0, 4.0, 3.0)


def test_clearance_is_the_distance_to_the_nearest_surface_and_negative_inside(room):
    assert room.clearance(0.5, 1.5) == pytest.approx(0.5)        # to the table's left edge
    assert room.nearest(1.5, 1.5) == (pytest.approx(-0.5), room.obstacle("table"))
    assert room.fits(0.75, 1.5) and not room.fits(0.85, 1.5)
    assert room.touching(0.8, 1.5) is room.obstacle("table") and room.touching(0.5, 0.5) is None


def test_a_motion_stops_where_the_footprint_touches_and_names_what_it_hit(room):
    x, y, theta, hit = room.move(0.2, 1.5, 0.0, 1.0, 0.0, 2.0)
    assert (x, y, theta, hit.id) == (pytest.approx(0.8, abs=1e-4), 1.5, 0.0, "table")
    assert room.fits(x, y)
    # from there it may drive away, but not further in
    assert room.move(x, y, 0.0, -0.5, 0.0, 1.0)[3] is None
    assert room.move(x, y, 0.0, 0.5, 0.0, 1.0)[0] == pytest.approx(x, abs=1e-4)


def test_a_fast_motion_does_not_jump_over_a_thin_wall(room):
    x, _y, _theta, hit = room.move(3.0, 0.5, 0.0, 100.0, 0.0, 1.0)
    assert (x, hit.id) == (pytest.approx(3.8, abs=1e-4), "wall")


def test_laser_rays_end_at_the_obstacles_edges(room):
    right, up = room.cast(0.5, 1.5, [0.0, math.pi / 2]).tolist()
    assert right == pytest.approx(0.5)                   # the table's left edge at x = 1
    assert up == pytest.approx(1.5)                      # the wedge's corner at (0.5, 3)
    assert room.cast(3.0, 0.5, [0.0]).tolist() == [pytest.approx(1.0)]   # the wall at x = 4
    assert World([], 0.1).cast(0, 0, [0.0, 1.0]).tolist() == [math.inf, math.inf]


@pytest.mark.parametrize("data, problem", [
    ({"radius": 0, "obstacles": []}, "radius"),
    ({"radius": 0.2, "obstacles": [{"id": "a", "rect": [1, 1, 0, 2]}]}, r"obstacles\[0\]: rect"),
    ({"radius": 0.2, "obstacles": [{"id": "a", "rect": [0, 0, 1, 1], "circle": [0, 0, 1]}]}, "exactly one"),
    ({"radius": 0.2, "obstacles": [{"id": "a", "polygon": [[0, 0], [1, 1]]}]}, "at least 3"),
    ({"radius": 0.2, "obstacles": [{"id": "a", "kind": "lava", "rect": [0, 0, 1, 1]}]}, "kind"),
    ({"radius": 0.2, "obstacles": [{"name": "x", "rect": [0, 0, 1, 1]}]}, "id"),
])
def test_bad_world_data_is_refused_naming_the_problem(data, problem):
    with pytest.raises(ValueError, match=problem):
        World.from_data(data)
