"""Texts in profile and toolbox files: a plain string, or one text per language."""

DEFAULT_LANGUAGE = "en"


def is_localized(value) -> bool:
    """True for a mapping like ``{en: "drive", de: "fahre"}``: language codes only, English present."""
    return (
        isinstance(value, dict)
        and DEFAULT_LANGUAGE in value
        and all(isinstance(key, str) and len(key) == 2 and key.islower() for key in value)
    )


def localize(value, language: str):
    """Resolve every localized text inside ``value`` (recursively) for ``language``.

    Falls back to English where a translation is missing.
    """
    if is_localized(value):
        text = value.get(language)
        return value[DEFAULT_LANGUAGE] if text is None else text
    if isinstance(value, dict):
        return {key: localize(item, language) for key, item in value.items()}
    if isinstance(value, list):
        return [localize(item, language) for item in value]
    return value
