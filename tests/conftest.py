import sys
from pathlib import Path

from hypothesis import settings

sys.path.insert(0, str(Path(__file__).parent))

# Deterministic property tests: the same examples on every run and machine.
settings.register_profile("repro", derandomize=True, max_examples=200, deadline=None)
settings.load_profile("repro")
