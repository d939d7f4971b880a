"""The simulated TurtleBot's room as data: walls and boxes, one World for its laser and its bumper.

Everything is in the odometry frame (metres, x forward from where the robot starts, y to its
left): the robot starts at the origin facing +x, 0.5 m from the wall behind it. The room is
given by its inside ``(x_min, y_min, x_max, y_max)``; its four walls are solid rectangles
``WALL`` thick around it, and the boxes are axis-aligned rectangles, named by the colour the
view paints them. The SDK's ``World`` does the geometry: what the laser sees is exactly what
the robot bumps into (the laser's 360 rays x 20 edges with numpy: about 0.2 ms a scan).
"""
from rockly_desktop.sdk import Obstacle, World, profile_texts

TEXTS = profile_texts(__file__)    # the profile's catalogue (locale/): the names and the bump message

ROOM = (-0.5, -1.5, 3.5, 1.5)        # a 4 m x 3 m room
BOXES = (
    (1.90, -0.30, 2.30, 0.10),       # a 40 cm box straight ahead of the start
    (1.35, 1.10, 1.95, 1.35),        # a long one by the far left wall
    (0.50, 0.55, 0.90, 0.95),        # one on the left, nearer the start
)
ROBOT_RADIUS = 0.105                 # m, the TurtleBot3 Burger's footprint as a circle
WALL = 0.07                          # m, as thick as the view draws the walls
# the boxes' names (keys of the catalogue), in the order of the view's colours (palette.BOX_COLOURS)
BOX_NAMES = ("the_red_box", "the_blue_box", "the_yellow_box", "the_green_box", "the_purple_box")
WALL_NAME = "the_wall"


def _rectangle(values, what):
    """The corners of ``(x_min, y_min, x_max, y_max)``; ValueError naming ``what`` unless min < max."""
    x0, y0, x1, y1 = (float(v) for v in values)
    if not (x0 < x1 and y0 < y1):
        raise ValueError(f"{what} must be (x_min, y_min, x_max, y_max) with min < max, not {values!r}")
    return ((x0, y0), (x1, y0), (x1, y1), (x0, y1))


class Arena(World):
    """The room ``room`` with ``boxes`` in it and a TurtleBot of ``radius``: the SDK's World of them."""

    def __init__(self, room=ROOM, boxes=BOXES, radius=ROBOT_RADIUS):
        self.room = tuple(float(v) for v in room)
        _rectangle(self.room, "the room")
        self.boxes = tuple(tuple(float(v) for v in box) for box in boxes)
        x0, y0, x1, y1 = self.room
        walls = {"wall_front": (x1, y0 - WALL, x1 + WALL, y1 + WALL),
                 "wall_back": (x0 - WALL, y0 - WALL, x0, y1 + WALL),
                 "wall_left": (x0, y1, x1, y1 + WALL), "wall_right": (x0, y0 - WALL, x1, y0)}
        obstacles = [Obstacle(name, TEXTS(WALL_NAME), _rectangle(rect, "a wall"), "wall")
                     for name, rect in walls.items()]
        for index, box in enumerate(self.boxes):
            obstacles.append(Obstacle(f"box_{index + 1}", TEXTS(BOX_NAMES[index % len(BOX_NAMES)]),
                                      _rectangle(box, "a box")))
        super().__init__(obstacles, radius, area=self.room)

    @property
    def size(self):
        """(width, depth) of the room in metres."""
        return self.room[2] - self.room[0], self.room[3] - self.room[1]


def bumped(obstacle_id=None):
    """"The TurtleBot bumped into ..." (a LocalText) for an obstacle id of an Arena (``something`` when unknown)."""
    kind, _, number = str(obstacle_id).partition("_")
    name = "something"
    if kind == "wall":
        name = WALL_NAME
    elif kind == "box" and number.isdigit() and int(number) > 0:
        name = BOX_NAMES[(int(number) - 1) % len(BOX_NAMES)]
    return TEXTS("bumped_into", thing=TEXTS(name))
