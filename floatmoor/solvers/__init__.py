"""floatmoor.solvers"""
