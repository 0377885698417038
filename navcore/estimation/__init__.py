"""Estimation: one Kalman filter and its relatives for all four papers.

Modules
-------
kalman
    prediction, Joseph-form update, information form.
riccati
    steady state of the scalar Riccati recursion.
discretize
    Van Loan discretisation and the first-order transition.
covariance
    linear covariance analysis over a measurement schedule.
layout
    named state layouts.
covariance_analysis
    truth-versus-filter covariance analysis of an aided INS (missions, schedules).
federated
    local velocity estimators, federated fusion and its correlation-free bound.
lmmse
    linear MMSE estimation with a nonrandom nuisance vector.
ekf_ins_gnss
    tightly coupled indirect feedback INS/GNSS EKF, batched over Monte Carlo runs.

The specialised modules are imported from their own paths
(``from navcore.estimation.federated import ...``); the core is re-exported here.
"""

from navcore.estimation.covariance import CovarianceHistory, Measurement, propagate_covariance
from navcore.estimation.discretize import first_order_transition, van_loan
from navcore.estimation.kalman import (
    KalmanUpdate,
    covariance_from_information,
    information_from_covariance,
    information_update,
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
    "covariance_from_information",
    "first_order_transition",
    "information_from_covariance",
    "information_update",
    "kf_predict",
    "kf_update",
    "propagate_covariance",
    "scalar_riccati_iterate",
    "scalar_riccati_steady_state",
    "symmetrize",
    "van_loan",
]
