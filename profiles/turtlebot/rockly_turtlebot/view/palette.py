"""Every named colour of the view, and the laser's colour scale (closer is warmer)."""
from PySide6.QtGui import QColor

# --- the map ------------------------------------------------------------------------------------
OUTSIDE = QColor("#DCEBF2")
TILES = (QColor("#FFF6E2"), QColor("#F8EBCF"))
TILE_SEAM = QColor(170, 140, 90, 60)
WALL = QColor("#3F4E6B")
WALL_TOP = QColor("#5C6E91")
BOX_COLOURS = (("#FF6B6B", "#C94848"), ("#4D96FF", "#2F6CC4"), ("#FFC93C", "#D19A12"),
               ("#6BCB77", "#3F9A4B"), ("#B983FF", "#8452C9"))
SHADOW = QColor(30, 40, 70, 50)
MAP_BORDER = QColor("#C7D3E3")
TRAIL = QColor("#2E86DE")
SEEN = QColor(255, 255, 255, 110)     # the floor the laser sees

# --- the robot ----------------------------------------------------------------------------------
PLATE = QColor("#2F3542")            # the TurtleBot's round plate; nothing else uses it (tests look for it)
PLATE_EDGE = QColor("#171B24")
PLATE_RING = QColor("#454C5C")
WHEEL = QColor("#111318")
TREAD = QColor("#3A3F4A")
LIDAR = QColor("#D9DEE7")
LIDAR_EDGE = QColor("#8A93A6")
LIDAR_WINDOW = QColor("#FF7A1A")
FRONT = QColor("#3BD16F")
BUMP = QColor("#FF3B3B")
BUMP_GLOW = QColor("#FFD23F")

# --- the panel ----------------------------------------------------------------------------------
PANEL_BG = QColor("#EEF2F8")
INK = QColor("#243047")
INK_SOFT = QColor("#6A7590")
RADAR_BG = QColor("#1E2A44")
RADAR_RING = QColor(255, 255, 255, 45)
BAR_BG = QColor("#E3E8F2")
DRIVE = QColor("#2E86DE")
TURN = QColor("#F5A623")
BATTERY_OK = QColor("#2FBF71")
BATTERY_LOW = QColor("#F5A623")
BATTERY_EMPTY = QColor("#E5383B")


def distance_colour(distance, far=2.0):
    """Red right at the robot, through orange, yellow and green to blue at ``far`` metres and beyond."""
    t = max(0.0, min(1.0, (distance - 0.12) / max(0.01, far - 0.12)))
    return QColor.fromHsvF(0.6 * t ** 0.8, 0.85, 0.97)
