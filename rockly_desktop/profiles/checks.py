"""Deeper checks of a profile that need its code: does every module it names import, and do
the templates call real commands?"""
import inspect
import re

from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles.manifest import MANIFEST_FIELDS, MANIFEST_NAME

_ROBOT_CALL = re.compile(r"\brobot\.(\w+)\s*\(")
_CODE_FIELDS = tuple(spec.name for spec in MANIFEST_FIELDS if spec.kind == "import")


def code_problems(profile) -> list:
    """Every problem with the profile's code, as ManifestErrors: each ``module:Name`` the manifest
    names must import (a syntax error, an exception or ``sys.exit`` while importing is named),
    the commands must be a class, and every ``robot.NAME(`` in a template must be one of its commands."""
    problems, loaded = [], {}
    for field_name in _CODE_FIELDS:
        if profile.manifest.get(field_name):
            try:
                loaded[field_name] = profile.load_object(field_name)
            except ManifestError as error:
                problems.append(error)
    commands = loaded.get("api")
    if commands is not None and not inspect.isclass(commands):
        problems.append(ManifestError(profile.root / MANIFEST_NAME, "api", f"{profile.api_target} is not a class"))
    elif commands is not None:
        blocks_file = profile.root / profile.manifest["blocks"]
        for spec in profile.blocks:
            for name in _ROBOT_CALL.findall(spec.code):
                if not callable(getattr(commands, name, None)) or name.startswith("_"):
                    problems.append(ManifestError(blocks_file, f"blocks[{spec.type}].python.code",
                                                  f"calls robot.{name}(), which {commands.__name__} does not have"))
    return problems


def check_commands(profile) -> None:
    """Raise the first of ``code_problems(profile)`` (a ManifestError), if there is one."""
    problems = code_problems(profile)
    if problems:
        raise problems[0]
