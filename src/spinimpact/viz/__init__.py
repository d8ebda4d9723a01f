"""Pictures and reports: Matplotlib figures, the HTML page and the terminal report.

Matplotlib and Rich are imported only when a figure or a report is made, so
``import spinimpact`` stays light.
"""
