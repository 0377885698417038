"""Estimation: one Kalman filter and its relatives for all four papers.

Modules
-------
kalman
    prediction, Joseph-form update, information form.
riccati
    steady state of the scalar Riccati recursion.
discretize
    one discretiser (Van Loan, nilpotent and series methods) and the truncated transitions.
covariance
    linear covariance analysis over a measurement schedule, and the error covariance of a
    filter that ignores a measurement bias.
layout
    named state layouts.
federated
    local velocity estimators, federated fusion and its correlation-free bound.
lmmse
    linear MMSE estimation with a nonrandom nuisance vector.

The INS/GNSS filter and the covariance analysis of an aided INS, which need the inertial
and GNSS models, are in :mod:`navcore.integration`.

The specialised modules are imported from their own paths
(``from navcore.estimation.federated import ...``); the core is re-exported here.
"""

from navcore.estimation.covariance import (
    CovarianceHistory,
    Measurement,
    biased_filter_error_covariance,
    propagate_covariance,
)
from navcore.estimation.discretize import discretize, first_order_transition, taylor_transition
from navcore.estimation.kalman import (
    KalmanUpdate,
    covariance_from_information,
    information_from_covariance,
    information_update,
    joseph_update,
    kf_predict,
    kf_update,
    symmetrize,
)
from navcore.estimation.layout import StateBlock, StateLayout
from navcore.estimation.riccati import (
    ScalarSteadyState,
    scalar_riccati_iterate,
    scalar_riccati_steady_state,
)

__all__ = [
    "CovarianceHistory",
    "KalmanUpdate",
    "Measurement",
    "ScalarSteadyState",
    "StateBlock",
    "StateLayout",
    "biased_filter_error_covariance",
    "covariance_from_information",
    "discretize",
    "first_order_transition",
    "information_from_covariance",
    "information_update",
    "joseph_update",
    "kf_predict",
    "kf_update",
    "propagate_covariance",
    "scalar_riccati_iterate",
    "scalar_riccati_steady_state",
    "symmetrize",
    "taylor_transition",
]
