"""Layer 4: views of results (LaTeX documents and tables, plots).  Works on
expressions and on objects passed in; imports no contact class."""
