"""The laser's scan, worked out once per snapshot and drawn twice: on the map (the floor it sees lit
up, thin rays to what is near, a bright dot on every hit, closer is warmer) and in the panel's radar.

``Scan`` turns the ranges into hits with numpy; painting then costs a few milliseconds: rays are
1-pixel cosmetic lines drawn without antialiasing (Qt's fast path) and reach only hits within
RAY_RANGE; the dots go out in BUCKETS colour groups, one pen each.
"""
import math

import numpy
from PySide6.QtCore import QLineF, QPointF, Qt
from PySide6.QtGui import QPainter, QPolygonF

from rockly_desktop.sdk import nearest_reading
from rockly_desktop.sdk_view import cosmetic_pen, with_alpha

from . import model
from .palette import SEEN, distance_colour

BUCKETS = 8         # hits are drawn in this many colour groups
COLOUR_RANGE = 2.0  # metres from red to blue
RAY_EVERY = 2       # a ray to every second hit ...
RAY_RANGE = 1.0     # ... that is this close (metres)


def bucket_colour(bucket):
    return distance_colour((bucket + 0.5) * COLOUR_RANGE / BUCKETS)


class Scan:
    """The hits of one snapshot's scan: beam index, distance, direction in the robot frame, colour group."""

    def __init__(self, snapshot):
        self.ranges = model.scan(snapshot)
        ranges = numpy.array(self.ranges, dtype=float)
        near, far = model.limits(snapshot)
        self.x, self.y, self.theta = model.pose(snapshot)
        self.near, self.far = near, far
        if ranges.size == 0:
            self.index = numpy.zeros(0, dtype=int)
            self.distance = self.angle = numpy.zeros(0)
            self.bucket = numpy.zeros(0, dtype=int)
            return
        with numpy.errstate(invalid="ignore"):
            valid = ((ranges >= near) & (ranges <= far)) | (ranges == -numpy.inf)
        self.index = numpy.flatnonzero(valid)
        self.distance = numpy.where(ranges[valid] == -numpy.inf, near, ranges[valid])
        self.angle = self.index * (2 * math.pi / ranges.size)       # counter-clockwise from ahead
        self.bucket = numpy.minimum(BUCKETS - 1, (self.distance / COLOUR_RANGE * BUCKETS).astype(int))

    def __len__(self):
        return int(self.index.size)

    def nearest_ahead(self):
        """The nearest hit ahead as the robot's commands and the Robot state panel see it (the SDK's
        ``nearest_reading``), or None."""
        if not self.ranges:
            return None
        nearest = nearest_reading(self.ranges, 0.0, 2 * math.pi / len(self.ranges), self.near, self.far)
        return nearest if math.isfinite(nearest) else None

    def closest_angle(self):
        """The direction (robot frame) of the shortest reading, or None."""
        return float(self.angle[int(numpy.argmin(self.distance))]) if len(self) else None

    def map_points(self):
        """(x, y) of every hit in map metres, as two arrays."""
        angles = self.theta + self.angle
        return self.x + self.distance * numpy.cos(angles), self.y + self.distance * numpy.sin(angles)


def _points(xs, ys):
    return [QPointF(x, y) for x, y in zip(xs.tolist(), ys.tolist(), strict=True)]


def paint_scan(p, scan, u):
    """The scan on the map, painted in map metres (the painter's transform is the map's)."""
    if not len(scan):
        return
    xs, ys = scan.map_points()
    points = _points(xs, ys)
    origin = QPointF(scan.x, scan.y)
    # what the laser sees: the polygon through its hits (beams that see nothing leave a gap to the robot)
    outline = []
    gaps = set((numpy.flatnonzero(numpy.diff(scan.index) != 1) + 1).tolist())
    for k, point in enumerate(points):
        if k in gaps:
            outline.append(origin)
        outline.append(point)
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(SEEN)
    p.drawPolygon(QPolygonF(outline))
    dot = max(2.5, 4.0 * u)
    buckets, indices = scan.bucket.tolist(), scan.index.tolist()
    for bucket in sorted(set(buckets), reverse=True):     # near hits on top
        members = [k for k, b in enumerate(buckets) if b == bucket]
        colour = bucket_colour(bucket)
        if (bucket + 0.5) * COLOUR_RANGE / BUCKETS < RAY_RANGE:
            p.setPen(cosmetic_pen(with_alpha(colour, 0.55 - 0.5 * bucket / BUCKETS), 1.0))
            p.setRenderHint(QPainter.RenderHint.Antialiasing, False)   # thin rays: 5x faster, hardly different
            p.drawLines([QLineF(origin, points[k]) for k in members if indices[k] % RAY_EVERY == 0])
            p.setRenderHint(QPainter.RenderHint.Antialiasing, True)
        p.setPen(cosmetic_pen(colour, dot, round_caps=True))
        p.drawPoints([points[k] for k in members])


def paint_radar_hits(p, scan, centre, radius, dot):
    """The hits in a round radar around ``centre`` (pixels, y down): ahead is up, the scale the square
    root of the distance, so what is near gets the room."""
    if not len(scan):
        return
    r = radius * numpy.sqrt(numpy.minimum(1.0, scan.distance / scan.far))
    angles = math.pi / 2 + scan.angle
    points = _points(centre.x() + r * numpy.cos(angles), centre.y() - r * numpy.sin(angles))
    buckets = scan.bucket.tolist()
    for bucket in sorted(set(buckets), reverse=True):
        p.setPen(cosmetic_pen(bucket_colour(bucket), dot))
        p.drawPoints([points[k] for k, b in enumerate(buckets) if b == bucket])
