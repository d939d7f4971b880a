"""Reading a profile's YAML files with errors that name the file and the line."""
from pathlib import Path

import yaml

from rockly_desktop.core.errors import ManifestError

# libyaml's safe loader when PyYAML was built with it (several times faster), else Python's.
_SAFE_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


def read_yaml_mapping(path: Path) -> dict:
    """Load a YAML file whose top level must be a mapping."""
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise ManifestError(path, None, "the file does not exist") from None
    except (OSError, UnicodeDecodeError) as error:
        raise ManifestError(path, None, f"the file cannot be read ({error})") from None
    try:
        data = yaml.load(text, Loader=_SAFE_LOADER)
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        where = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        problem = getattr(error, "problem", None) or str(error)
        raise ManifestError(path, None, f"this is not valid YAML{where}: {problem}") from None
    if not isinstance(data, dict):
        raise ManifestError(path, None, "the file must contain a mapping (key: value lines) at the top level")
    return data
