"""What a program built, as text (the model inspector) and as a picture (snapshot): the agent's eyes
and the viewer's drawings.

``view`` reads one execution of the program into a system view (bodies, connectors, loads, states);
``answer`` writes it as the inspector's text; ``snapshot`` draws it. Nothing here ever sees a
ground truth: a view is made from the program's own execution only.
"""
