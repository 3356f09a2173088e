"""stub"""
def run_bench(repeat): return "todo"
