"""Layer 6: checking published formulas (claims files) against the engine,
the paper's figures as data, and the reports of a check.

``spec`` (the claims file: claims and figures), ``references`` (independent
numerical references), ``derive`` (what the engine derives for a claim: the
one user of the contact API here), ``sampling``, ``check`` (the verdicts),
``results`` (their records), ``figures`` and ``report`` (the outputs)."""
from .batch import check_file, check_paper
from .check import check_claim
from .results import ClaimResult, PaperResult, FAILS, HOLDS, HOLDS_IF, UNDECIDED
from .spec import Claim, Form, Paper, claim_from_cli, claim_from_dict, load_paper, paper_from_dict

__all__ = ["Claim", "ClaimResult", "Form", "Paper", "PaperResult", "check_claim", "check_file", "check_paper",
           "claim_from_cli", "claim_from_dict", "load_paper", "paper_from_dict", "FAILS", "HOLDS", "HOLDS_IF",
           "UNDECIDED"]
