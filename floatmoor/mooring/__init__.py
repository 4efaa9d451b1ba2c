"""floatmoor.mooring"""
