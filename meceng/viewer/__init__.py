"""A static site to look inside runs (``meceng view``): every task record in one filterable
table, a page per record with its stages, differences, plots, programs and conversation.

``traces`` is the part a run uses while it runs (it keeps trajectories and part surfaces small
for the viewer); the rest reads finished (or running) run folders.
"""
