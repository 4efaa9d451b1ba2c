"""floatmoor.post"""
