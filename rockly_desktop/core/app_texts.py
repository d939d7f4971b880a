"""Rockly's own texts in every language: the catalogue in ``resources/locale`` (see ``core.catalogue``).

The window's texts, why a run stopped, a teacher's limits and the commands' shared errors
are all here; a profile's own texts are in its own catalogue (``locale/`` beside its manifest).
"""
from functools import lru_cache

from rockly_desktop.core import paths
from rockly_desktop.core.catalogue import Catalogue, LocalText


@lru_cache(maxsize=None)
def app_catalogue() -> Catalogue:
    """The catalogue of Rockly's own texts."""
    return Catalogue(paths.data_root() / "resources" / "locale")


def app_text(key: str, language: str, **values) -> str:
    """Rockly's text ``key`` in ``language`` (English where there is no translation), ``values`` filled in."""
    return app_catalogue().text(key, language, **values)


def app_local_text(key: str, **values) -> LocalText:
    """Rockly's text ``key`` with ``values``, to be put into a language where it is shown."""
    return app_catalogue()(key, **values)


def languages() -> tuple:
    """The languages Rockly speaks: English and one for every ``.po`` file of its catalogue."""
    return app_catalogue().languages


def language_name(language: str) -> str:
    """A language's name in itself ("Deutsch"), for choosing it."""
    return app_text("language_name", language)
