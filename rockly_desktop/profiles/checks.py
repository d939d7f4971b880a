"""Deeper checks of a profile that need its code: do the templates call real commands?"""
import inspect
import re

from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles.manifest import MANIFEST_NAME

_ROBOT_CALL = re.compile(r"\brobot\.(\w+)\s*\(")


def check_commands(profile) -> None:
    """Import the profile's command class and check every ``robot.NAME(`` in a template exists.

    Raises ManifestError naming the block and the missing command.
    """
    commands = profile.load_object("api")
    if not inspect.isclass(commands):
        raise ManifestError(profile.root / MANIFEST_NAME, "api", f"{profile.manifest['api']} is not a class")
    blocks_file = profile.root / profile.manifest["blocks"]
    for spec in profile.blocks:
        for name in _ROBOT_CALL.findall(spec.code):
            if not callable(getattr(commands, name, None)) or name.startswith("_"):
                raise ManifestError(blocks_file, f"blocks[{spec.type}].python.code",
                                    f"calls robot.{name}(), which {commands.__name__} does not have")
