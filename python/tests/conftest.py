import os

import pytest

SOURCE_DIR = os.environ["BRDFTAB_SOURCE_DIR"]
TABLES = os.path.join(SOURCE_DIR, "tables")


@pytest.fixture
def tables():
    return TABLES
