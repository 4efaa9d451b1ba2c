"""floatmoor.io"""
