"""Test settings shared by every test module.

Hypothesis explores new random cases on every local run; CI (``.ci/run`` sets
``HYPOTHESIS_PROFILE=ci``) runs the same derandomized cases every time, so that a
submission lands or not on its own merits. A case found locally is printed with its
reproduction blob.
"""

from __future__ import annotations

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
settings.register_profile("dev", print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "dev"))
