"""A simulated robot's solid world, declared as data: walls and furniture the robot cannot enter.

A profile's simulator describes its world once (in Python or in a YAML file read with
``load_world``) and asks it where the robot's round footprint may go, what its laser sees and
what it bumped into; it writes no geometry of its own. Coordinates are map metres (x to the
right, y up). A world's data::

    radius: 0.275                  # the robot's footprint, a circle around its centre
    area: [-1.0, -2.5, 5.0, 2.5]   # x0, y0, x1, y1 of the map: navigation goals outside it are refused
    obstacles:
      - id: sofa
        kind: furniture            # or wall
        name: the_sofa                     # a key of the profile's catalogue (load_world's texts)
        rect: [0.1, 1.6, 2.1, 2.42]        # or polygon: [[x, y], ...], or circle: [x, y, radius]

A name is a key of the profile's catalogue (``Texts``: "the sofa", German "das Sofa"), or a
plain text shown in every language. It is written as it follows "bumped into" (in German:
"gegen", the accusative: "den Tisch").
Obstacles are polygons; a circle becomes a 16-sided one, so the laser and the bumper see the
same shape. Nothing here imports Qt: the same world serves ``rockly run`` and the window.
"""
import hashlib
import math
from dataclasses import dataclass
from pathlib import Path

import yaml

from rockly_desktop.core.yaml_nesting import MAX_NESTING, too_deep

CONTACT = 1e-4          # m: a footprint this close to an obstacle touches it
STEP = 0.01             # m: the longest straight piece a swept motion checks at once
TURN_STEP = 0.1         # rad: the largest turn a swept motion checks at once
CIRCLE_SIDES = 16
KINDS = ("wall", "furniture")


@dataclass(frozen=True)
class Obstacle:
    """A named solid shape: ``points`` is its outline, a polygon of (x, y) corners."""

    id: str
    label: object           # a catalogue's LocalText (or a plain text) naming it
    points: tuple
    kind: str = "furniture"

    def name(self, language: str = "en") -> str:
        """The obstacle's name in ``language`` (English when its catalogue has none in that language)."""
        in_language = getattr(self.label, "in_language", None)
        return (in_language(language) if in_language is not None else str(self.label or "")) or self.id

    @property
    def bounds(self):
        """(x0, y0, x1, y1) of the smallest rectangle around it."""
        xs, ys = [x for x, _ in self.points], [y for _, y in self.points]
        return min(xs), min(ys), max(xs), max(ys)

    def distance(self, x: float, y: float) -> float:
        """Distance from (x, y) to the outline: negative inside."""
        nearest = min(_segment_distance(x, y, a, b) for a, b in _edges(self.points))
        return -nearest if _inside(x, y, self.points) else nearest


def _edges(points):
    return zip(points, points[1:] + points[:1])


def _segment_distance(x, y, a, b):
    (ax, ay), (bx, by) = a, b
    dx, dy = bx - ax, by - ay
    length = dx * dx + dy * dy
    t = 0.0 if length == 0 else max(0.0, min(1.0, ((x - ax) * dx + (y - ay) * dy) / length))
    return math.hypot(x - ax - t * dx, y - ay - t * dy)


def _inside(x, y, points):
    inside = False
    for (ax, ay), (bx, by) in _edges(points):
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            inside = not inside
    return inside


def rectangle(x0, y0, x1, y1):
    """The corners of an axis-aligned rectangle; ValueError unless x0 < x1 and y0 < y1 (finite)."""
    values = tuple(float(v) for v in (x0, y0, x1, y1))
    if not all(map(math.isfinite, values)) or values[0] >= values[2] or values[1] >= values[3]:
        raise ValueError(f"a rectangle must be (x_min, y_min, x_max, y_max) with min < max, not {values!r}")
    x0, y0, x1, y1 = values
    return ((x0, y0), (x1, y0), (x1, y1), (x0, y1))


def circle(x, y, radius, sides=CIRCLE_SIDES):
    """A regular polygon with ``sides`` corners around (x, y), its edges touching the circle from outside."""
    outer = float(radius) / math.cos(math.pi / sides)
    return tuple((x + outer * math.cos(math.tau * k / sides), y + outer * math.sin(math.tau * k / sides))
                 for k in range(sides))


class World:
    """Obstacles and a round robot among them: clearance, swept motion stopped at contact, laser rays.

    ``area`` (x0, y0, x1, y1) is the map a navigation goal must lie in (None: anywhere).
    """

    def __init__(self, obstacles, radius: float, area=None):
        self.obstacles = tuple(obstacles)
        self.radius = float(radius)
        if not (math.isfinite(self.radius) and self.radius > 0):
            raise ValueError(f"the robot's radius must be a positive number, not {radius!r}")
        self.area = None if area is None else rectangle(*area)[0] + rectangle(*area)[2]
        import numpy  # here, not with the module: the SDK brings this module in while the editor's page loads

        starts, vectors = [], []
        for obstacle in self.obstacles:
            for (ax, ay), (bx, by) in _edges(obstacle.points):
                starts.append((ax, ay))
                vectors.append((bx - ax, by - ay))
        self._a = numpy.array(starts, dtype=float).reshape(-1, 2)    # (S, 2): where each edge starts
        self._e = numpy.array(vectors, dtype=float).reshape(-1, 2)   # (S, 2): the edge's vector

    @classmethod
    def from_data(cls, data: dict, where: str = "the world", texts=None):
        """A World from its data (see the module's docstring), names from the catalogue ``texts``;
        ValueError naming what is wrong."""
        if not isinstance(data, dict):
            raise ValueError(f"{where}: expected a mapping with radius and obstacles")
        obstacles = [_obstacle(entry, f"{where}: obstacles[{index}]", texts)
                     for index, entry in enumerate(data.get("obstacles") or [])]
        return cls(obstacles, data.get("radius", 0), data.get("area"))

    def fingerprint(self) -> str:
        """A short id of the world's geometry (area, robot radius, obstacles and their outlines): the same
        rooms give the same id, and a recording made in one world is not shown in another."""
        shape = repr((self.area, self.radius, [(o.id, o.kind, tuple((round(x, 6), round(y, 6)) for x, y in o.points))
                                               for o in self.obstacles]))
        return hashlib.sha256(shape.encode("utf-8")).hexdigest()[:16]

    def obstacle(self, obstacle_id: str) -> Obstacle:
        """The obstacle with this id; KeyError when there is none."""
        for obstacle in self.obstacles:
            if obstacle.id == obstacle_id:
                return obstacle
        raise KeyError(obstacle_id)

    # --- the robot's body ---------------------------------------------------------------

    def nearest(self, x: float, y: float):
        """(distance, obstacle) of the obstacle nearest to (x, y): distance negative inside it; (inf, None)."""
        best = (math.inf, None)
        for obstacle in self.obstacles:
            distance = obstacle.distance(x, y)
            if distance < best[0]:
                best = (distance, obstacle)
        return best

    def clearance(self, x: float, y: float) -> float:
        """Distance from (x, y) to the nearest obstacle's surface (negative inside one)."""
        return self.nearest(x, y)[0]

    def fits(self, x: float, y: float) -> bool:
        """True when the robot's footprint at (x, y) overlaps nothing."""
        return self.clearance(x, y) >= self.radius

    def touching(self, x: float, y: float):
        """The obstacle the footprint at (x, y) touches or overlaps, or None."""
        distance, obstacle = self.nearest(x, y)
        return obstacle if distance < self.radius + CONTACT else None

    def in_area(self, x: float, y: float) -> bool:
        """True when (x, y) lies on the map (always, for a world without an area)."""
        if self.area is None:
            return True
        x0, y0, x1, y1 = self.area
        return x0 <= x <= x1 and y0 <= y <= y1

    def move(self, x, y, theta, linear, angular, dt):
        """Unicycle motion for ``dt`` s, stopped at the first contact: (x, y, theta, obstacle hit or None).

        The path is followed in pieces of at most 1 cm (nothing is jumped over); a piece that
        would overlap something is cut where the footprint touches it (to 0.1 mm).
        """
        pieces = max(1, math.ceil(abs(linear) * dt / STEP), math.ceil(abs(angular) * dt / TURN_STEP))
        step = dt / pieces
        for _ in range(pieces):
            nx, ny, ntheta = unicycle(x, y, theta, linear, angular, step)
            if not self.fits(nx, ny) and self.clearance(nx, ny) < self.clearance(x, y) + 1e-12:
                low, high = 0.0, 1.0
                while (high - low) * abs(linear) * step > CONTACT / 2:
                    middle = (low + high) / 2
                    mx, my, _ = unicycle(x, y, theta, linear, angular, step * middle)
                    low, high = (middle, high) if self.fits(mx, my) else (low, middle)
                x, y, theta = unicycle(x, y, theta, linear, angular, step * low)
                return x, y, theta, self.nearest(nx, ny)[1]
            x, y, theta = nx, ny, ntheta
        return x, y, theta, None

    # --- the laser ----------------------------------------------------------------------

    def cast(self, x, y, angles):
        """Distance from (x, y) along each direction in ``angles`` (radians) to the nearest obstacle edge
        (``inf`` where a ray hits nothing), all rays at once."""
        import numpy  # already loaded by __init__: a dictionary look-up

        angles = numpy.asarray(angles, dtype=float)
        if not len(self._a):
            return numpy.full(angles.shape, numpy.inf)
        dx, dy = numpy.cos(angles)[:, None], numpy.sin(angles)[:, None]       # (N, 1)
        ex, ey = self._e[:, 0], self._e[:, 1]                                  # (S,)
        wx, wy = self._a[:, 0] - x, self._a[:, 1] - y                          # (S,)
        denominator = dx * ey - dy * ex                                        # (N, S)
        with numpy.errstate(divide="ignore", invalid="ignore"):
            t = (wx * ey - wy * ex) / denominator       # along the ray
            s = (wx * dy - wy * dx) / denominator       # along the edge, 0..1 when hit
        hit = (numpy.abs(denominator) > 1e-12) & (t >= 0) & (s >= -1e-9) & (s <= 1 + 1e-9)
        return numpy.where(hit, t, numpy.inf).min(axis=1)


def unicycle(x, y, theta, v, w, dt):
    """Drive at ``v`` m/s turning at ``w`` rad/s for ``dt`` s from (x, y, theta), integrated exactly."""
    if abs(w) < 1e-9:
        return x + v * dt * math.cos(theta), y + v * dt * math.sin(theta), theta
    end = theta + w * dt
    return (x + v / w * (math.sin(end) - math.sin(theta)), y - v / w * (math.cos(end) - math.cos(theta)),
            math.remainder(end, math.tau))


def load_world(path, texts=None) -> World:
    """The World a YAML file declares (see the module's docstring), its names keys of the catalogue ``texts``;
    ValueError naming the file and what is wrong."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
        depth = too_deep(text)
        if depth is not None:
            raise ValueError(f"{path}: this YAML nests up to {depth} levels deep; Rockly reads at most {MAX_NESTING}")
        data = yaml.load(text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
    except (OSError, UnicodeDecodeError, yaml.YAMLError) as error:
        raise ValueError(f"{path}: {error}") from None
    return World.from_data(data, str(path), texts)


def _obstacle(entry, where, texts=None):
    if not isinstance(entry, dict):
        raise ValueError(f"{where}: expected a mapping with id, name and rect, polygon or circle")
    obstacle_id, kind, name = entry.get("id"), entry.get("kind", "furniture"), entry.get("name") or ""
    if not isinstance(obstacle_id, str) or not obstacle_id:
        raise ValueError(f"{where}: id must be a text")
    if kind not in KINDS:
        raise ValueError(f"{where}: kind must be one of {', '.join(KINDS)}, not {kind!r}")
    if not isinstance(name, str):
        raise ValueError(f"{where}: name must be a text (a key of the profile's catalogue)")
    shapes = [key for key in ("rect", "polygon", "circle") if key in entry]
    if len(shapes) != 1:
        raise ValueError(f"{where}: give exactly one of rect, polygon or circle")
    try:
        if shapes[0] == "rect":
            points = rectangle(*entry["rect"])
        elif shapes[0] == "circle":
            cx, cy, radius = (float(v) for v in entry["circle"])
            if not radius > 0:
                raise ValueError("the radius must be positive")
            points = circle(cx, cy, radius)
        else:
            points = tuple((float(px), float(py)) for px, py in entry["polygon"])
            if len(points) < 3 or not all(map(math.isfinite, sum(points, ()))):
                raise ValueError("a polygon needs at least 3 finite corners")
    except (TypeError, ValueError) as error:
        raise ValueError(f"{where}: {shapes[0]}: {error}") from None
    return Obstacle(obstacle_id, texts(name) if texts is not None and name in texts else name, points, kind)
