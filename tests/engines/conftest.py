"""The ``engine`` fixture: each installed engine in turn."""

import pytest

from spinimpact import engines as E


@pytest.fixture(params=E.ENGINES)
def engine(request):
    if not E.available(request.param):
        pytest.skip(f"{request.param} is not installed (the [engines] extra)")
    return request.param
