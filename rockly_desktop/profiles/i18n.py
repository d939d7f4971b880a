"""Texts in profile and toolbox files: a plain string, or one text per language (``{en: ..., de: ...}``);
a language not spelled out there comes from the profile's catalogue (``locale/LANG.po``), by the English text."""

DEFAULT_LANGUAGE = "en"


def is_localized(value) -> bool:
    """True for a mapping like ``{en: "drive", de: "fahre"}``: language codes only, English present."""
    return (
        isinstance(value, dict)
        and DEFAULT_LANGUAGE in value
        and all(isinstance(key, str) and len(key) == 2 and key.islower() for key in value)
    )


def localize(value, language: str, catalogues=()):
    """Resolve every localized text inside ``value`` (recursively) for ``language``.

    A language the text does not spell out is looked up by its English text in ``catalogues``
    (gettext entries without msgctxt: a profile's ``locale/LANG.po``, then Rockly's); English
    where none has it.
    """
    if is_localized(value):
        text = value.get(language)
        if text is None:
            text = next((found for found in (catalogue.translate(value[DEFAULT_LANGUAGE], language)
                                             for catalogue in catalogues) if found), None)
        return value[DEFAULT_LANGUAGE] if text is None else text
    if isinstance(value, dict):
        return {key: localize(item, language, catalogues) for key, item in value.items()}
    if isinstance(value, list):
        return [localize(item, language, catalogues) for item in value]
    return value
