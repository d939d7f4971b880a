"""A block pack as one zip file, to share between laptops.

The zip holds the pack's folder (``PACK_ID/pack.yaml``, ...). Importing checks every entry
before anything is written (no absolute path, no ``..``, no link, no name twice, a bounded size), unpacks
into a hidden folder beside the packs, reads it as a pack (manifest, blocks, toolbox), checks
that it can join the profile it adds to, and only then puts it in place.
"""
import os
import shutil
import stat
import tempfile
import zipfile
from pathlib import Path, PurePosixPath

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles.packs.making import install_folder
from rockly_desktop.profiles.packs.merge import merge_problem
from rockly_desktop.profiles.packs.pack import PACK_MANIFEST, is_pack_folder, load_pack, user_packs_dir
from rockly_desktop.profiles.packs.validation import BlockMakerError

MAX_ENTRIES = 1000
MAX_BYTES = 20 * 1024 * 1024  # unpacked: a pack is a few YAML files


def export_pack(pack, output) -> Path:
    """Write ``pack`` (a Pack) to the zip file ``output``, all or nothing; returns its path."""
    output = Path(output)
    output.parent.mkdir(parents=True, exist_ok=True)
    handle, temp_name = tempfile.mkstemp(prefix=f".{output.name}.", suffix=".tmp", dir=output.parent)
    os.close(handle)
    try:
        with zipfile.ZipFile(temp_name, "w", zipfile.ZIP_DEFLATED) as archive:
            for path in sorted(pack.root.rglob("*")):
                relative = path.relative_to(pack.root)
                hidden = any(part.startswith(".") for part in relative.parts)
                if path.is_file() and not path.is_symlink() and not hidden:
                    archive.write(path, f"{pack.id}/{relative.as_posix()}")
        os.replace(temp_name, output)
    except BaseException:
        Path(temp_name).unlink(missing_ok=True)
        raise
    return output


def _unsafe(path, name):
    return BlockMakerError(app_local_text("pack_zip_unsafe", path=path, name=name))


def _checked_entries(path: Path, archive: zipfile.ZipFile) -> tuple:
    """``(top folder or '', [(entry, relative path)])`` after refusing anything unsafe."""
    entries, total = [], 0
    infos = archive.infolist()
    if len(infos) > MAX_ENTRIES:
        raise BlockMakerError(app_local_text("pack_zip_bad", path=path, problem=f"more than {MAX_ENTRIES} entries"))
    for info in infos:
        name = info.filename
        pure = PurePosixPath(name)
        if ("\\" in name or pure.is_absolute() or ".." in pure.parts or ":" in name
                or stat.S_ISLNK(info.external_attr >> 16)):
            raise _unsafe(path, name)
        total += info.file_size
        if total > MAX_BYTES:
            raise BlockMakerError(app_local_text("pack_zip_bad", path=path,
                                                 problem=f"it unpacks to more than {MAX_BYTES // 2**20} MB"))
        if not info.is_dir():
            entries.append((info, pure))
    names = {pure for _info, pure in entries}
    if len(names) < len(entries):  # zip listers show the first copy, unpacking keeps the last: which is the pack?
        twice = next(pure for pure in names if sum(entry == pure for _info, entry in entries) > 1)
        raise BlockMakerError(app_local_text("pack_zip_bad", path=path, problem=f"it holds {twice} twice"))
    if PurePosixPath(PACK_MANIFEST) in names:
        return "", entries
    tops = {pure.parts[0] for pure in names}
    if len(tops) == 1 and PurePosixPath(next(iter(tops)), PACK_MANIFEST) in names:
        top = next(iter(tops))
        return top, [(info, pure.relative_to(top)) for info, pure in entries]
    raise BlockMakerError(app_local_text("pack_zip_bad", path=path, problem=f"it holds no {PACK_MANIFEST}"))


def import_pack(path, profiles: dict, folder=None, replace: bool = False):
    """Install the pack in the zip file ``path`` into ``folder`` (default: the user's packs);
    ``profiles`` are the installed profiles by id without packs (a registry's ``base_profiles``;
    a clash with another installed pack shows in the registry's ``pack_errors``). Returns the Pack.

    Raises BlockMakerError, having written nothing, for a file that is no pack, an unsafe entry,
    a broken manifest, a profile that is not installed, and (unless ``replace``) a pack installed already.
    """
    path = Path(path)
    folder = Path(folder) if folder is not None else user_packs_dir()
    try:
        archive = zipfile.ZipFile(path)
    except (OSError, zipfile.BadZipFile) as error:
        raise BlockMakerError(app_local_text("pack_zip_bad", path=path, problem=error)) from None
    folder.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=".import-", dir=folder))
    try:
        with archive:
            _top, entries = _checked_entries(path, archive)
            for info, relative in entries:
                target = staging.joinpath(*relative.parts)
                target.parent.mkdir(parents=True, exist_ok=True)
                with archive.open(info) as source, open(target, "wb") as sink:
                    shutil.copyfileobj(source, sink)
        try:
            pack = load_pack(staging)
        except ManifestError as error:  # named by its place in the zip, not in the hidden folder it was unpacked to
            problem = str(error).replace(f"{staging}{os.sep}", "")
            raise BlockMakerError(app_local_text("pack_zip_bad", path=path, problem=problem)) from None
        return _install(pack, staging, profiles, folder, replace)
    except (OSError, zipfile.BadZipFile) as error:
        raise BlockMakerError(app_local_text("pack_zip_bad", path=path, problem=error)) from None
    finally:
        shutil.rmtree(staging, ignore_errors=True)


def _install(pack, staging: Path, profiles: dict, folder: Path, replace: bool):
    if pack.adds_to not in profiles:
        raise BlockMakerError(app_local_text("pack_profile_missing", profile=pack.adds_to,
                                             installed=", ".join(profiles) or "-"))
    problem = merge_problem(profiles[pack.adds_to], pack)
    if problem is not None:
        raise BlockMakerError(problem)
    target = folder / pack.id
    if is_pack_folder(target) and not replace:
        try:
            version = load_pack(target).version
        except ManifestError:
            version = "?"
        raise BlockMakerError(app_local_text("pack_zip_exists", pack=pack.id, version=version))
    install_folder(staging, target)
    return load_pack(target)
