"""Services for one landing trial: events and incidents from the kernel's step records, results."""
