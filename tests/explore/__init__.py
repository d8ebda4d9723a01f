"""Tests of the explorer (spinimpact.explore)."""
