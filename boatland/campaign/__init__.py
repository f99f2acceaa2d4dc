"""Monte Carlo slip-probability campaigns (seed 002 §3.3, §4.2): plans, execution, store, statistics."""

from boatland.campaign.plan import Campaign, load_campaign
from boatland.campaign.runner import run_campaign

__all__ = ["Campaign", "load_campaign", "run_campaign"]
