"""floatmoor.metocean"""
