"""The component catalog the prompts document (paper section 2.2): each component's menu line,
its context and a working example.

``component`` (the ``Component`` and ``Catalog`` types, text helpers) <- the component lists
(``bodies``, ``joints``, ``springs``, ``loads`` gathered by ``rigid``; ``part``; ``flexible``)
<- ``catalogs`` (the catalog of each task kind).
"""
