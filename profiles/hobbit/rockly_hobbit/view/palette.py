"""Every named colour of the simulator view: the robot, the room, the panel and the emotions' accents."""
from PySide6.QtGui import QColor

# --- the robot and what it does on the map -------------------------------------------------

BASE_COLOR = QColor("#1FB3C8")       # HOBBIT's round base; nothing else uses it (tests look for it)
BASE_EDGE = QColor("#117888")
BUMPER = QColor("#FFC83D")
BODY = QColor("#FBFBFD")
BODY_EDGE = QColor("#8A93AC")
HEAD = QColor("#EEF2F8")
VISOR = QColor("#26325A")
ARM = QColor("#FF9431")
ARM_EDGE = QColor("#C2621A")
GRIPPER = QColor("#3C4560")
TRAIL = QColor("#8C5CF0")
GOAL = QColor("#FF4B6E")
VIEW_CONE = QColor("#FFD23F")
VIEW_CONE_EDGE = QColor("#F2A100")
SOS = QColor("#E5383B")

MOTION_COLOURS = {"idle": "#9AA4BA", "moving": "#2FBF71", "turning": "#FFB020", "navigating": "#FF4B6E"}

# --- the room ---------------------------------------------------------------------------------

LAWN = QColor("#D3EDC5")
WOOD = (QColor("#F5DDB6"), QColor("#F1D6A9"), QColor("#F7E3C1"), QColor("#F2D9AF"))
SEAM = QColor(196, 150, 95, 90)
WALL_FILL = QColor("#8E86CF")
WALL_EDGE = QColor("#6C64AE")
GRID = QColor(110, 80, 40, 42)
MAP_BORDER = QColor("#C9CEE6")

# --- the panel --------------------------------------------------------------------------------

PANEL_BG = QColor("#EEF0FA")
INK = QColor("#27304D")
INK_SOFT = QColor("#69718C")
FACE_BG = QColor("#243160")
FACE_BG_SLEEP = QColor("#161D3C")
LID_EDGE = QColor("#9FB2EA")
IRIS = QColor("#42B4F5")
IRIS_DARK = QColor("#1A6ED0")
HINT = QColor("#6A4FD8")             # the tablet's "waiting for your answer", hourglass and caret

EMOTION_ACCENT = {
    "HAPPY": "#FFC23D", "VHAPPY": "#FF6FAE", "LTIRED": "#A99BD9", "VTIRED": "#7C6CC4", "CONCERNED": "#FF9A3D",
    "SAD": "#4D8DFF", "WONDERING": "#22C2B0", "NEUTRAL": "#9AA4BA", "SLEEPING": "#4A56A6",
}
