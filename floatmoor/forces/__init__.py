"""floatmoor.forces"""
