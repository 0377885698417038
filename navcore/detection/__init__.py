"""Detection theory: Neyman-Pearson relations, Chernoff and Gallager bounds, jamming bounds on
false alarms and ambiguous detections, multiple-access noise and its ROC, Zakai bandwidth."""
