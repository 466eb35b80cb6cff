EF (S2 & !S3)
