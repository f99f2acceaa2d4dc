"""Monte Carlo slip-probability campaigns (Grøtting 2015 §3.3, §4.2): plans, execution, store, statistics,
the decision table; :func:`open_store` reads a store as an xarray Dataset."""

from boatland.campaign.dataset import open_store
from boatland.campaign.plan import Campaign, load_campaign
from boatland.campaign.runner import run_campaign

__all__ = ["Campaign", "load_campaign", "run_campaign", "open_store"]
