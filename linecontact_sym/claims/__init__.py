"""Layer 6: checking published formulas (claims files) against the engine,
and the reports of a check."""
from .check import (Claim, ClaimResult, Form, Paper, PaperResult, check_claim, check_file, check_paper,
                    claim_from_cli, claim_from_dict, load_paper, paper_from_dict, FAILS, HOLDS, HOLDS_IF,
                    UNDECIDED)

__all__ = ["Claim", "ClaimResult", "Form", "Paper", "PaperResult", "check_claim", "check_file", "check_paper",
           "claim_from_cli", "claim_from_dict", "load_paper", "paper_from_dict", "FAILS", "HOLDS", "HOLDS_IF",
           "UNDECIDED"]
