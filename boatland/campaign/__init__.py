"""Monte Carlo slip-probability campaigns (Grøtting 2015 §3.3, §4.2): plans, execution, store, statistics,
the decision table; :func:`open_store` reads a store as an xarray Dataset.

The package is callable: ``boatland.campaign("demo", seeds=2)`` is :func:`boatland.campaign.job.campaign` (run or
resume a campaign, return its store's Dataset) — the name a notebook reaches for, whether ``boatland.campaign``
was first imported as this package or looked up on ``boatland``.
"""

import sys
import types

from boatland.campaign.dataset import open_store
from boatland.campaign.job import campaign, campaign_path
from boatland.campaign.plan import Campaign, load_campaign
from boatland.campaign.runner import run_campaign

__all__ = ["Campaign", "load_campaign", "run_campaign", "open_store", "campaign", "campaign_path"]


class _CallablePackage(types.ModuleType):
    """This package, callable as :func:`boatland.campaign.job.campaign`."""

    def __call__(self, source, **kwargs):
        return campaign(source, **kwargs)


sys.modules[__name__].__class__ = _CallablePackage
