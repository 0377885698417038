"""Per-paper modules: published inputs (typed data with units and locators), claims, errata.

Each module defines module-level ``CLAIMS`` (list of :class:`navcore.claims.Claim`) and
``ERRATA`` (list of :class:`navcore.claims.Erratum`). Modules are discovered by
:mod:`navcore.ledger.registry`; name them ``<paper>_<section>.py`` (``sp_architectures``,
``atc10_jamming``). Paper names belong here, not in the model subpackages.
"""
