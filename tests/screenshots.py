"""Pictures of widgets a test drew, to look at: kept in $ROCKLY_SCREENSHOTS when it is set."""
import os


def screenshot(widget, name: str):
    """Save ``widget`` as ``name``.png in $ROCKLY_SCREENSHOTS (nothing when it is not set)."""
    folder = os.environ.get("ROCKLY_SCREENSHOTS")
    if folder:
        widget.grab().save(os.path.join(folder, f"{name}.png"))
