from typing import Any

import pandas as pd

from . import Scenario

def report(scenario: Scenario) -> dict: ...
def evaluate(scenario: Scenario, heights_m: Any, period_s: Any = ..., *, threads: int = ...) -> pd.DataFrame: ...
