"""floatmoor.hydro"""
