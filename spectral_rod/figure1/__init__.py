"""Figure 1 of the paper: the digitised points (:mod:`.data`) and how every printed point was
made (:mod:`.forensics`)."""
