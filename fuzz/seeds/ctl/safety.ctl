AG !(V1 & V3)
