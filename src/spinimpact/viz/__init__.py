"""Pictures and reports: Matplotlib figures (:mod:`~spinimpact.viz.plots`; the maps
over the incidence in :mod:`~spinimpact.viz.maps`), the HTML page
(:mod:`~spinimpact.viz.html`) and the terminal report (:mod:`~spinimpact.viz.report`),
the two reports rendering the same tables from one builder
(:mod:`~spinimpact.viz.tables`).

Matplotlib and Rich are imported only when a figure or a report is made, so
``import spinimpact`` stays light.
"""
