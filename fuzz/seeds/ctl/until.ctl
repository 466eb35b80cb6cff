A[ !S2 U S1 ] -> AG AF S1
