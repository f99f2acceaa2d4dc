"""The planner's site: compass directions (:mod:`~boatland.site.compass`), the site's weather — a scatter
diagram or a hindcast (:mod:`~boatland.site.weather`) — the limit of every sea state at every landing, one
spectrum or wind sea + swell (:mod:`~boatland.site.limits`), in each sea state's own current and wind
(:mod:`~boatland.site.flows`), or from a rare-event campaign's time-domain limits (:mod:`~boatland.site.tables`), weather windows (:mod:`~boatland.site.windows`) and
the operability of one or more vessels over it (:mod:`~boatland.site.operability`, figure
:mod:`~boatland.site.figures`). ``boatland operability`` is its command."""

from boatland.site.compass import global_bearing, landing_bearing, relative_direction, towards_global
from boatland.site.flows import (CURRENT_DIRECTION_STEP, CURRENT_SPEED_STEP, WIND_DIRECTION_STEP, WIND_SPEED_STEP,
                                 flow_setups, sea_limits)
from boatland.site.limits import DIRECTION_STEP, PART_SHAPES, SeaLimits, wave_limits
from boatland.site.tables import LimitsTable, table_limits
from boatland.site.operability import MONTHS, Operability, operability, side_by_side, table_operability
from boatland.site.weather import Weather, read_weather
from boatland.site.windows import Persistence, persistence, run_lengths

__all__ = ["CURRENT_DIRECTION_STEP", "CURRENT_SPEED_STEP", "DIRECTION_STEP", "MONTHS", "PART_SHAPES",
           "WIND_DIRECTION_STEP", "WIND_SPEED_STEP", "LimitsTable", "Operability", "Persistence", "SeaLimits",
           "Weather", "flow_setups", "global_bearing", "landing_bearing", "operability", "persistence", "read_weather",
           "relative_direction", "run_lengths", "sea_limits", "side_by_side", "table_limits", "table_operability",
           "towards_global", "wave_limits"]
