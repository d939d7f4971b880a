"""What the maker offers for a profile, and its preview of a block on the editor page."""
from pathlib import Path

from rockly_desktop.core.app_texts import app_catalogue
from rockly_desktop.profiles.blocks import block_spec
from rockly_desktop.profiles.packs.generate import block_definition


def category_choices(profile, language: str = "en") -> list:
    """``[(name in language, English name, colour)]`` of the profile's own toolbox categories (with
    its packs'), for the maker's category and colour choices; shared categories are left out."""
    choices = []
    for category in profile.toolbox_categories:
        if "shared" in category or "contents" not in category:
            continue
        name = category["name"]
        english = name.get("en") if isinstance(name, dict) else name
        choices.append((profile.localize(name, language), english, category.get("colour", "")))
    return choices


def preview_block(block, profile, language: str = "en") -> dict:
    """The made ``block`` as one entry of ``Profile.editor_config``'s ``blocks`` (definition in
    ``language`` and generator), so a preview page can define and draw it; ManifestError when the
    generated definition does not read back (a problem ``validation`` reports first)."""
    spec = block_spec(block_definition(block), Path("(preview)"))
    return spec.editor_config(language, (profile.texts, app_catalogue()))
