"""Reading a profile's YAML files with errors that name the file and the line."""
from pathlib import Path

import yaml

from rockly_desktop.core.errors import ManifestError

# libyaml's safe loader when PyYAML was built with it (several times faster), else Python's.
_SAFE_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


def _first_alias(text: str):
    """The first alias (``*name``) in YAML ``text`` as (line, column), or None.

    Aliases are refused: nine lines of them expand into billions of values (a "billion
    laughs"), and no profile needs them. Only text with a ``*`` is parsed for them.
    """
    if "*" not in text:
        return None
    for event in yaml.parse(text, Loader=_SAFE_LOADER):
        if isinstance(event, yaml.AliasEvent):
            return event.start_mark.line + 1, event.start_mark.column + 1
    return None


def read_yaml_mapping(path: Path) -> dict:
    """Load a YAML file whose top level must be a mapping."""
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise ManifestError(path, None, "the file does not exist") from None
    except (OSError, UnicodeDecodeError) as error:
        raise ManifestError(path, None, f"the file cannot be read ({error})") from None
    try:
        alias = _first_alias(text)
        if alias is not None:
            raise ManifestError(path, None, f"YAML aliases (*name) are not allowed in profile files "
                                            f"(line {alias[0]}, column {alias[1]}): write the value out")
        data = yaml.load(text, Loader=_SAFE_LOADER)
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        where = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        problem = getattr(error, "problem", None) or str(error)
        raise ManifestError(path, None, f"this is not valid YAML{where}: {problem}") from None
    if not isinstance(data, dict):
        raise ManifestError(path, None, "the file must contain a mapping (key: value lines) at the top level")
    return data
