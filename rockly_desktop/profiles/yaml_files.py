"""Reading a profile's YAML files with errors that name the file and the line.

Parsing YAML was most of reading the profiles at start-up, so what a file held is also
kept as JSON in the user's cache folder, with the hash of the text it came from; a file
whose text changed is parsed again. A cache that cannot be read or written is no error.
"""
import hashlib
import json
import os
import tempfile
from pathlib import Path

from rockly_desktop.core import paths
from rockly_desktop.core.errors import ManifestError
from rockly_desktop.core.yaml_nesting import MAX_NESTING, too_deep

CACHE_FORMAT = 1


def _first_alias(yaml, loader, text: str):
    """The first alias (``*name``) in YAML ``text`` as (line, column), or None.

    Aliases are refused: nine lines of them expand into billions of values (a "billion
    laughs"), and no profile needs them. Only text with a ``*`` is parsed for them.
    """
    if "*" not in text:
        return None
    for event in yaml.parse(text, Loader=loader):
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
    digest = hashlib.sha256(text.encode("utf-8")).hexdigest()
    entry = _cache_entry(path)
    data = _cached(entry, digest)
    if data is None:
        data = _parse(path, text)
        _keep(entry, digest, data)
    return data


def _parse(path: Path, text: str) -> dict:
    import yaml  # only when a file is not in the cache: importing PyYAML takes a while too

    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)  # libyaml's when PyYAML has it: several times faster
    depth = too_deep(text)
    if depth is not None:
        raise ManifestError(path, None, f"this YAML nests up to {depth} levels deep; Rockly reads at most "
                                        f"{MAX_NESTING}")
    try:
        alias = _first_alias(yaml, loader, text)
        if alias is not None:
            raise ManifestError(path, None, f"YAML aliases (*name) are not allowed in profile files "
                                            f"(line {alias[0]}, column {alias[1]}): write the value out")
        data = yaml.load(text, Loader=loader)
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        where = f" at line {mark.line + 1}, column {mark.column + 1}" if mark else ""
        problem = getattr(error, "problem", None) or str(error)
        raise ManifestError(path, None, f"this is not valid YAML{where}: {problem}") from None
    if not isinstance(data, dict):
        raise ManifestError(path, None, "the file must contain a mapping (key: value lines) at the top level")
    return data


def _cache_entry(path: Path) -> Path:
    """The cache file of the YAML file at ``path`` (one per file, whatever its text)."""
    name = hashlib.sha256(str(Path(path).resolve()).encode("utf-8")).hexdigest()[:32]
    return paths.user_cache_dir() / "yaml" / f"{name}.json"


def _cached(entry: Path, digest: str):
    """What the cache holds for the text with hash ``digest``, or None."""
    try:
        kept = json.loads(entry.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(kept, dict) or kept.get("format") != CACHE_FORMAT or kept.get("sha256") != digest:
        return None
    data = kept.get("data")
    return data if isinstance(data, dict) else None


def _keep(entry: Path, digest: str, data: dict):
    """Write ``data`` to the cache if JSON gives it back exactly (not a date, not a number as a key)."""
    try:
        text = json.dumps({"format": CACHE_FORMAT, "sha256": digest, "data": data}, ensure_ascii=False)
    except (TypeError, ValueError):
        return
    if json.loads(text)["data"] != data:
        return
    try:
        entry.parent.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile("w", encoding="utf-8", dir=entry.parent, delete=False) as stream:
            stream.write(text)
        os.replace(stream.name, entry)  # readers see the old entry or the new one, never half
    except OSError:
        pass
