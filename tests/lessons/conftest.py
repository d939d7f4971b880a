"""Fixtures of the lesson tests: the installed profiles by id."""
import pytest

from rockly_desktop.profiles.registry import ProfileRegistry


@pytest.fixture(scope="session")
def profiles():
    """{id: Profile} of the installed profiles."""
    return ProfileRegistry.discover().profiles
